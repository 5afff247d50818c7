// The closed-box preparation and the helpers of the tests built on it
// (see closed_box_test.h).
#include "lab/closed_box_test.h"

#include "core/error.h"

namespace grainlab {

namespace {

DirectShearSpec closed_box(const DirectShearSpec& spec) {
  DirectShearSpec p = spec;
  p.test = "direct-shear";
  p.box.gap = 0;  // the halves' slabs meet: one rigid ring
  return p;
}

}  // namespace

ClosedBoxTest::ClosedBoxTest(const DirectShearSpec& spec) : spec_(spec), prep_(closed_box(spec)) {
  prep_.end_after_consolidation();
}

std::vector<std::string> ClosedBoxTest::series_columns() const {
  std::vector<std::string> c = own_columns();
  c.insert(c.end(), observer_columns_.begin(), observer_columns_.end());
  return c;
}

void ClosedBoxTest::set_sample_observer(std::vector<std::string> columns, SampleObserver observer) {
  observer_columns_ = std::move(columns);
  observer_ = std::move(observer);
}

void ClosedBoxTest::observe(std::vector<double>& row) const {
  if (!observer_) return;
  const std::vector<double> extra = observer_(*this);
  if (extra.size() != observer_columns_.size())
    throw RunError(
        fmt::format("sample observer gave {} values for {} columns", extra.size(), observer_columns_.size()));
  row.insert(row.end(), extra.begin(), extra.end());
}

std::vector<SummaryValue> ClosedBoxTest::preparation_summary() const {
  std::vector<SummaryValue> v;
  for (const SummaryValue& s : prep_.summary())
    if (s.group == "preparation" || s.key == "mean_equivalent_diameter_m") v.push_back(s);
  return v;
}

void ClosedBoxTest::save_preparation(ByteWriter& out) const {
  const std::vector<std::uint8_t> bytes = prep_.save();
  out.u64(bytes.size());
  out.raw(bytes);
}

void ClosedBoxTest::load_preparation(ByteReader& in) { prep_.load(in.raw(in.count(1))); }

void ClosedBoxTest::save_bodies(ByteWriter& out, const std::vector<BodyState>& bodies) {
  out.u64(bodies.size());
  for (const BodyState& b : bodies) out.vec(b.x), out.vec(b.v), out.vec(b.w), out.quat(b.q);
}

std::vector<BodyState> ClosedBoxTest::load_bodies(ByteReader& in) {
  std::vector<BodyState> bodies(in.count(13 * 8));
  for (BodyState& b : bodies) b.x = in.vec(), b.v = in.vec(), b.w = in.vec(), b.q = in.quat();
  return bodies;
}

}  // namespace grainlab
