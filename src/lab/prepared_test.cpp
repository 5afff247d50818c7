// The base of the tests a SpecimenPreparation prepares (see prepared_test.h).
#include "lab/prepared_test.h"

#include "core/error.h"

namespace grainlab {

PreparedTest::PreparedTest(const LabSpec& spec, std::unique_ptr<SpecimenPreparation> preparation)
    : spec_(spec), prep_(std::move(preparation)) {}

const std::vector<std::string>& PreparedTest::own_columns() const {
  static const std::vector<std::string> none;
  return none;
}

std::string PreparedTest::status_line() const { return prep_->status_line(); }

std::string PreparedTest::phase_note() const { return prep_->phase_note(); }

std::vector<SummaryValue> PreparedTest::summary() const { return prep_->summary(); }

double PreparedTest::specimen_volume() const { return prep_->box_area() * world().state.walls[Cap].x.z(); }

double PreparedTest::boundary_stress() const { return prep_->normal_stress(); }

std::vector<std::string> PreparedTest::series_columns() const {
  std::vector<std::string> c = own_columns();
  c.insert(c.end(), observer_columns_.begin(), observer_columns_.end());
  return c;
}

void PreparedTest::set_sample_observer(std::vector<std::string> columns, SampleObserver observer) {
  observer_columns_ = std::move(columns);
  observer_ = std::move(observer);
}

void PreparedTest::observe(std::vector<double>& row) const {
  if (!observer_) return;
  const std::vector<double> extra = observer_(*this);
  if (extra.size() != observer_columns_.size())
    throw RunError(
        fmt::format("sample observer gave {} values for {} columns", extra.size(), observer_columns_.size()));
  row.insert(row.end(), extra.begin(), extra.end());
}

void PreparedTest::save_bodies(ByteWriter& out, const std::vector<BodyState>& bodies) {
  out.u64(bodies.size());
  for (const BodyState& b : bodies) out.vec(b.x), out.vec(b.v), out.vec(b.w), out.quat(b.q);
}

std::vector<BodyState> PreparedTest::load_bodies(ByteReader& in) {
  std::vector<BodyState> bodies(in.count(13 * 8));
  for (BodyState& b : bodies) b.x = in.vec(), b.v = in.vec(), b.w = in.vec(), b.q = in.quat();
  return bodies;
}

}  // namespace grainlab
