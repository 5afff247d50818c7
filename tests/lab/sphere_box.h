// Spheres (the glass-beads preset: analytic spheres of 0.71-0.84 mm) for the
// tests of the index densities and the preparation search: cheap contacts,
// and known packings to compare with.
#pragma once

#include "lab/direct_shear_spec.h"
#include "lab/index_densities.h"

namespace grainlab::testing_support {

// Glass beads, 4 sizes, in a box `diameters` d_max square and 5 d_max high.
inline DirectShearSpec sphere_spec(double diameters = 6) {
  DirectShearSpec s;
  s.grains.preset = "glass-beads";
  s.grains.shapes = 4;
  s.box.length = s.box.width = diameters * s.grains.d_max;
  s.box.height = 5 * s.grains.d_max;
  s.seed = 3;
  s.numerics.threads = 2;
  return s;
}

// The index box of the sphere tests: 6 d_max square, 6 high (the command's
// default is 10 x 8; 6 keeps the tests in seconds, and the bulk measure
// stays 1.5 diameters from the walls).
inline IndexDensityOptions small_index_box() {
  IndexDensityOptions o;
  o.seeds = 1;
  o.box_diameters = 6;
  o.height_diameters = 6;
  return o;
}

}  // namespace grainlab::testing_support
