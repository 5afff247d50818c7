// The closed-box preparation (see closed_box_test.h).
#include "lab/closed_box_test.h"

namespace grainlab {

namespace {

LabSpec closed_box(const LabSpec& spec) {
  LabSpec p = spec;
  p.box.gap = 0;  // the halves' slabs meet: one rigid ring
  return p;
}

}  // namespace

ClosedBoxTest::ClosedBoxTest(const LabSpec& spec)
    : PreparedTest(spec, std::make_unique<SpecimenPreparation>(closed_box(spec))) {}

bool ClosedBoxTest::prepare(int max_steps) {
  if (prep_->advance(max_steps)) return false;
  for (int r = UpperXm; r <= Cap; ++r) world().state.walls[r].v.setZero();
  return true;
}

}  // namespace grainlab
