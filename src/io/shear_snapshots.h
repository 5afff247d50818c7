// ParaView snapshots of a direct shear run (DESIGN.md "Files a run writes"):
// grains/contacts/walls_NNNN.vtp and their .pvd collections (io/snapshot_vtk.h)
// in the run folder's paraview/ subfolder, in single precision.
//
// When: snapshot 0 at the start of shear; snapshot k at the first sample
// whose shear strain reaches k x output.snapshot_interval (samples are the
// only states every run, straight or resumed, passes through, so the
// snapshots of a resumed run are those of an uninterrupted one); and one
// after the last, numbered on, at the end of the test, unless the last
// sample was already written. snapshot_interval = 0: the start and the end
// only. Times in the .pvd files are the simulated time (s).
//
// Grain values: displacement (m) and rotation (rad) since the start of shear
// (LabTest::reference()), velocity (m/s), coordination (grain-
// grain contacts of each grain), and in_shear_band (1 for the grains whose
// reference centre is in the band of io/shear_analysis.h, else 0).
#pragma once

#include "io/snapshot_vtk.h"
#include "lab/lab_test.h"

#include <cstdint>
#include <filesystem>

namespace grainlab {

class ShearSnapshots {
 public:
  // Snapshots into run_folder/paraview. With `resume`, the collections keep
  // the entries an interrupted run wrote, and the schedule picks up from the
  // test's restored state.
  ShearSnapshots(const std::filesystem::path& run_folder, const LabTest& test, bool resume);

  // Call after every LabTest::advance(): writes a snapshot when the
  // test has just recorded a sample that is due (rules above).
  void update(const LabTest& test);

  // A run started from another run's prepared specimen (specimen.from), whose
  // state is that of the start of loading: that snapshot, as the run that
  // prepared the specimen wrote it.
  void write_loading_start(const LabTest& test) { write(test, 0); }

  // Call once the test is done: the final snapshot.
  void finish(const LabTest& test);

  const SnapshotWriter& writer() const { return writer_; }

 private:
  void write(const LabTest& test, int index);
  int index_for_strain(double strain) const;  // k such that strain >= k x interval (interval > 0)

  SnapshotWriter writer_;
  double interval_ = 0;
  std::size_t rows_seen_ = 0;
  int next_index_ = 0;
  std::int64_t last_step_ = -1;  // step of the last snapshot written by this process
};

}  // namespace grainlab
