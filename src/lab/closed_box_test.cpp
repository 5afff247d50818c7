// The closed-box preparation (see closed_box_test.h).
#include "lab/closed_box_test.h"

namespace grainlab {

LabSpec ClosedBoxTest::preparation_spec(const LabSpec& spec) {
  LabSpec p = spec;
  p.box.gap = 0;  // the halves' slabs meet: one rigid ring
  return p;
}

ClosedBoxTest::ClosedBoxTest(const LabSpec& spec)
    : ClosedBoxTest(spec, std::make_unique<SpecimenPreparation>(preparation_spec(spec))) {}

ClosedBoxTest::ClosedBoxTest(const LabSpec& spec, std::unique_ptr<SpecimenPreparation> preparation)
    : PreparedTest(spec, std::move(preparation)) {}

bool ClosedBoxTest::prepare(int max_steps) {
  if (prep_->advance(max_steps)) return false;
  for (int r = UpperXm; r <= Cap; ++r) world().state.walls[r].v.setZero();
  return true;
}

}  // namespace grainlab
