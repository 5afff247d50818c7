// The tiny direct shear box of the lab tests: 3.5 x 3.5 x 2.5 mm, about 90
// sub-angular grains of 120 faces (4 shapes), so a whole protocol runs in
// seconds.
#pragma once

#include "lab/direct_shear_spec.h"

namespace grainlab::testing_support {

inline DirectShearSpec tiny_box_spec() {
  DirectShearSpec spec;
  spec.box.length = 3.5e-3;
  spec.box.width = 3.5e-3;
  spec.box.height = 2.5e-3;
  spec.grains.shapes = 4;
  spec.grains.faces = 120;
  spec.seed = 5;
  // The densest this preparation makes in a box under five grains wide, where
  // the walls loosen the packing (measured: e = 0.62 to 0.63).
  spec.specimen.deposition_friction = 0.05;
  spec.specimen.void_ratio = 0.63;
  spec.specimen.tolerance = 0.02;
  return spec;
}

}  // namespace grainlab::testing_support
