// ParaView snapshots of a simulation (DESIGN.md "Files a run writes"): for
// snapshot NNNN, three PolyData files built from the Model and the State:
//
//   grains_NNNN.vtp    each grain's surface mesh at its pose (world frame, m),
//                      triangles; point data, constant over each grain: grain
//                      id, displacement (m), rotation angle (rad), velocity
//                      (m/s), coordination number, and any extra per-grain
//                      arrays the caller supplies.
//   contacts_NNNN.vtp  a line between the two grain centres per grain-grain
//                      contact (in_contact(), as World::contact_count counts;
//                      a pair touching at several places has one line each);
//                      cell data: the two grain ids, the sub-contact id within
//                      the pair (0 for convex grains), force magnitude, normal
//                      force, tangential force magnitude (N), unit normal
//                      (from the first grain to the second), force on the
//                      second grain (N, vector).
//   walls_NNNN.vtp     each wall as triangles: a box wall as its box, a plane
//                      wall as a square patch around its point; cell data:
//                      wall id, force the grains put on it (N, vector).
//
// SnapshotWriter writes them into a run folder and keeps grains.pvd,
// contacts.pvd and walls.pvd listing every snapshot with its time.
#pragma once

#include "dynamics/model.h"
#include "dynamics/state.h"
#include "io/vtk_writer.h"

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace grainlab {

// Per-grain values for grains_NNNN.vtp, one entry per grain; an empty vector
// leaves that array out of the file. The caller may fill them from any analysis.
struct GrainFields {
  std::vector<Vec3> displacement;          // m, from the reference pose
  std::vector<double> rotation;            // rad, angle of the rotation from the reference orientation
  std::vector<Vec3> velocity;              // m/s
  std::vector<std::int32_t> coordination;  // grain-grain contacts of each grain
  std::vector<VtkArray> extra;             // more arrays, one tuple per grain, written on its points as well
};

// Angle (rad, in [0, pi]) of the rotation taking orientation `ref` to `now`:
// 2 atan2(|v|, |w|) of dq = now ref^-1, so q and -q give the same angle.
// A local helper: swap for the analysis layer's rotation measure when it exists.
double snapshot_rotation_angle(const Quat& now, const Quat& ref);

// Number of touching grain-grain pairs of each grain (a pair touching at several places counts once).
std::vector<std::int32_t> grain_contact_counts(const State& state);

// The default per-grain values: velocity and coordination always; displacement
// and rotation from `reference` if given (same number of grains), else left empty.
GrainFields grain_fields(const State& state, const State* reference);

struct SnapshotOptions {
  int sphere_subdivisions = 2;    // icosphere level drawn for sphere shapes (20 * 4^s triangles)
  double plane_size = 0;          // m, side of the square drawn for a plane wall; 0 = twice the extent of the grains
  bool single_precision = false;  // Float32 instead of Float64 points and values in grains files (half the size)
};

// grains_NNNN.vtp contents. Throws std::invalid_argument if the State does not
// match the Model or a field has neither 0 nor one entry per grain.
PolyData grains_polydata(const Model& model, const State& state, const GrainFields& fields,
                         const SnapshotOptions& options = {});

// contacts_NNNN.vtp contents: one line per grain-grain contact, in pair order.
PolyData contacts_polydata(const State& state);

// walls_NNNN.vtp contents: each wall's triangles, in wall order.
PolyData walls_polydata(const Model& model, const State& state, const SnapshotOptions& options = {});

// Writes the three snapshot files into a run folder and keeps the .pvd collections up to date.
class SnapshotWriter {
 public:
  // Creates `folder` if needed (RunError if it cannot).
  explicit SnapshotWriter(std::filesystem::path folder, SnapshotOptions options = {});

  // Writes grains_/contacts_/walls_NNNN.vtp for snapshot `index` (>= 0) at
  // `time` (s) and adds them to grains.pvd, contacts.pvd, walls.pvd. Writing
  // an index again replaces its files and its time in the collections.
  void write(int index, double time, const Model& model, const State& state, const GrainFields& fields);
  // As above with grain_fields(state, reference); a null reference means the
  // grains' poses at this writer's first snapshot.
  void write(int index, double time, const Model& model, const State& state, const State* reference = nullptr);

  // Adds the entries of grains.pvd, contacts.pvd and walls.pvd already in the
  // folder (an interrupted run being resumed) to the collections, so that new
  // snapshots extend them; a missing .pvd is skipped (InputError for a bad one).
  void keep_existing_collections();

  const std::filesystem::path& folder() const { return folder_; }
  const PvdCollection& grains() const { return grains_; }
  const PvdCollection& contacts() const { return contacts_; }
  const PvdCollection& walls() const { return walls_; }

  // "grains_0007.vtp" for kind "grains" and index 7.
  static std::string file_name(std::string_view kind, int index);

 private:
  std::filesystem::path folder_;
  SnapshotOptions options_;
  PvdCollection grains_, contacts_, walls_;
  State first_;  // poses of the first snapshot (bodies only): the default reference
  bool have_first_ = false;
};

}  // namespace grainlab
