// ParaView snapshots during shear (schedule in shear_snapshots.h).
#include "io/shear_snapshots.h"

#include "io/shear_analysis.h"

#include <cmath>

namespace grainlab {

namespace {

constexpr double kStrainSlack = 1e-9;  // a sample that reaches k x interval up to rounding counts

SnapshotOptions snapshot_options() {
  SnapshotOptions o;
  o.single_precision = true;
  return o;
}

}  // namespace

ShearSnapshots::ShearSnapshots(const std::filesystem::path& run_folder, const LabTest& test, bool resume)
    : writer_(run_folder / "paraview", snapshot_options()), interval_(test.spec().output.snapshot_interval) {
  if (resume) writer_.keep_existing_collections();
  rows_seen_ = test.series().size();
  // Every snapshot due at or before the restored state was written before it
  // was saved (snapshots are taken at samples, before the checkpoint).
  if (rows_seen_ > 0) next_index_ = interval_ > 0 ? index_for_strain(test.progress()) + 1 : 1;
}

int ShearSnapshots::index_for_strain(double strain) const {
  return static_cast<int>(std::floor((strain + kStrainSlack) / interval_));
}

void ShearSnapshots::update(const LabTest& test) {
  const std::size_t rows = test.series().size();
  if (rows == rows_seen_) return;
  rows_seen_ = rows;  // advance() returns right after a sample: the state is that of the last row
  const double strain = test.progress();
  if (rows == 1 && next_index_ == 0) {
    write(test, 0);  // the start of shear
    next_index_ = 1;
    return;
  }
  if (interval_ > 0 && strain + kStrainSlack >= next_index_ * interval_) {
    const int k = index_for_strain(strain);
    write(test, k);
    next_index_ = k + 1;
  }
}

void ShearSnapshots::finish(const LabTest& test) {
  if (test.world().state.step == last_step_) return;  // the last sample is the final state, already written
  write(test, interval_ > 0 ? index_for_strain(test.progress()) + 1 : 1);
}

void ShearSnapshots::write(const LabTest& test, int index) {
  const World& w = test.world();
  const State ref = shear_reference_state(test);
  GrainFields fields = grain_fields(w.state, ref.bodies.size() == w.state.bodies.size() ? &ref : nullptr);
  if (!fields.displacement.empty()) {
    const BandAnalysis band = analyse_band(test, ref);
    fields.extra.push_back({"in_shear_band", 1, std::vector<std::int32_t>(band.mask.begin(), band.mask.end())});
  }
  writer_.write(index, w.state.time, w.model, w.state, fields);
  last_step_ = w.state.step;
}

}  // namespace grainlab
