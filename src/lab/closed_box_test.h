// A lab test in the shear box with its gap closed, so that its eight side
// slabs form one rigid ring: the specimen prepared there (lab/preparation.h:
// the same code, density target and checks as every test), then loaded its
// own way: the oedometer (lab/oedometer.h) and the triaxial test
// (lab/triaxial.h). A test adds its phases after the preparation's.
#pragma once

#include "lab/prepared_test.h"

namespace grainlab {

class ClosedBoxTest : public PreparedTest {
 public:
  // Builds the preparation of `spec` in the box with box.gap 0.
  explicit ClosedBoxTest(const LabSpec& spec);
  // Goes on from `preparation`, a preparation of preparation_spec(spec)
  // (the preparation search's trial that landed on the target).
  ClosedBoxTest(const LabSpec& spec, std::unique_ptr<SpecimenPreparation> preparation);

  // The spec the specimen is prepared with: spec's, the gap closed.
  static LabSpec preparation_spec(const LabSpec& spec);

 protected:
  // Advances the preparation; true once it is prepared, the upper slabs and
  // the cap then at rest (its servo lets go of the cap).
  bool prepare(int max_steps);
};

}  // namespace grainlab
