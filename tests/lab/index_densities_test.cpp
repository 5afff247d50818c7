// The grains' own index void ratios (lab/index_densities.h) of spheres fall
// in the ranges known for sphere packings, and the bulk measure of the
// packing density (lab/packing_density.h) is exact on a hand-built lattice.
#include "lab/index_densities.h"
#include "lab/packing_density.h"
#include "sphere_box.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace grainlab;

TEST(PackingDensity, SimpleCubicLatticeOfSpheres) {
  // Spheres of radius r on a cubic lattice of pitch 2r: phi = pi/6 in any
  // region that is a whole number of cells, wherever its faces cut spheres
  // (the cap fractions of a sphere cut by two opposite faces sum to one
  // cell's share).
  Model m;
  const double r = 1e-3;
  const Index sphere = m.add_sphere_shape(r);
  const Index mat = m.add_material(Material{});
  State s;
  for (int i = -5; i <= 5; ++i)
    for (int j = -5; j <= 5; ++j)
      for (int k = -5; k <= 5; ++k) {
        m.bodies.push_back(m.make_body(sphere, mat, 1.0));
        BodyState b;
        b.x = Vec3(i, j, k) * 2 * r;
        s.bodies.push_back(b);
      }
  const Vec3 lo(-4 * r + 0.3 * r, -4 * r, -4 * r), hi(4 * r + 0.3 * r, 4 * r, 4 * r);  // 4 x 4 x 4 cells, shifted
  EXPECT_NEAR(solid_fraction_in_region(m, s, lo, hi), std::numbers::pi / 6, 1e-12);
  EXPECT_NEAR(void_ratio_in_region(m, s, lo, hi), 6 / std::numbers::pi - 1, 1e-12);
}

// The spheres' indices, measured once for the tests below (about 20 s).
const IndexDensities& sphere_indices() {
  static const IndexDensities d =
      measure_index_densities(testing_support::sphere_spec(), testing_support::small_index_box());
  return d;
}

// KNOWN FAILURE since the exact box-sphere routine (6fc44e9) changed how the
// beads meet the box walls, kept visible (run with
// --gtest_also_run_disabled_tests): measured e_min = 0.612 (bulk) and the
// "loosest" e_max = 0.589, below e_min. The lattice deposition without a cap
// is not a loose state (issue 10, docs/direct_shear.md "Known limits"); the
// e_min bound 0.61 was one measurement (0.590) plus a margin. Re-enable when
// the loose preparation is fixed.
TEST(IndexDensities, DISABLED_FrictionlessSpheresReachRandomClosePacking) {
  const IndexDensities& d = sphere_indices();
  ASSERT_TRUE(d.settled());
  // Frictionless spheres compacted: random close packing, phi = 0.64 (e =
  // 0.5625; Scott & Kilgour 1969, Torquato et al. 2000); the bulk of a small
  // box, a size range of 0.84:0.71 and finite compaction allow phi 0.62-0.655,
  // e 0.53-0.61. Measured: e_min = 0.590 (bulk), 0.758 over the whole box.
  EXPECT_GT(d.e_min, 0.53);
  EXPECT_LT(d.e_min, 0.61);
  // The whole box (cap height) is looser than the bulk: the walls.
  EXPECT_GT(d.dense.front().whole_void_ratio, d.dense.front().void_ratio + 0.05);
  // The loosest preparation is looser than the densest (measured: e_max =
  // 0.626, only 0.036 above e_min; see the disabled test below).
  EXPECT_GT(d.e_max, d.e_min + 0.02);
}

// KNOWN FAILURE, kept visible (run with --gtest_also_run_disabled_tests):
// frictional spheres deposited without compaction should form a random loose
// packing, phi 0.55-0.60 (e 0.67-0.82; Onoda & Liniger 1990: 0.555 at the
// loosest limit; poured packings 0.58-0.60). This preparation gives e_max =
// 0.626 (phi 0.615): the grains fall from a lattice with 5 % gaps, so they
// barely collide and the pile collapses into a dense structure whatever the
// friction, and deposition at friction 0.6 or more never comes to rest
// (lab/preparation_search.h, kLoosestDepositionFriction). A looser
// preparation (random placement, gentle pluviation) and the contact problem
// at high friction are open (issue 10).
TEST(IndexDensities, DISABLED_FrictionalSpheresReachRandomLoosePacking) {
  const IndexDensities& d = sphere_indices();
  EXPECT_GT(d.e_max, 0.67);
  EXPECT_LT(d.e_max, 0.83);
}
