// The shear band from plain inputs (analysis/band_analysis.h) and the
// per-sample micromechanics (analysis/shear_sample.h) on a synthetic
// direct-shear field: grains from the floor to the cap, the upper half carried
// along by the box displacement, a linear ramp between.
#include "analysis/band_analysis.h"
#include "analysis/shear_sample.h"
#include "displacement_field.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace grainlab;
using namespace grainlab::analysis;

namespace {

using analysis_test::Field;
using analysis_test::kMm;

// 2000 grains evenly in reference height over (0, 10) mm; u(z) = 0 below 4 mm,
// d above 6 mm, linear between.
Field ramp(double d) {
  Field f;
  const int n = 2000;
  f.ref.bodies.resize(n);
  f.now.bodies.resize(n);
  for (int i = 0; i < n; ++i) {
    const double z = (i + 0.5) * (10 * kMm / n);
    const double u = d * std::clamp((z - 4 * kMm) / (2 * kMm), 0.0, 1.0);
    f.ref.bodies[i].x = Vec3(0.1 * kMm * (i % 7), 0, z);
    f.now.bodies[i].x = f.ref.bodies[i].x + Vec3(u, 0, 0);
  }
  return f;
}

}  // namespace

TEST(BandResult, LayersOfOneDiameterAndTheRampsBand) {
  const Field f = ramp(1 * kMm);
  // Cap at 10 mm, diameter 0.5 mm: 20 layers; strain 0.05 of a 20 mm box: d_h = 1 mm.
  const BandResult b = band_result(f.now, f.ref, {0.0, 10 * kMm, 0.5 * kMm, 0.05, 20 * kMm});
  EXPECT_EQ(b.profile_spec.layers, 20);
  EXPECT_DOUBLE_EQ(b.min_jump, 0.1 * 0.05 * 20 * kMm);
  ASSERT_TRUE(b.band.found);
  // A linear ramp from 4 to 6 mm: the band runs from 4.2 to 5.8 mm (shear_band.h),
  // to within the layer discretisation.
  EXPECT_NEAR(b.band.z_low, 4.2 * kMm, 0.1 * kMm);
  EXPECT_NEAR(b.band.z_high, 5.8 * kMm, 0.1 * kMm);
  // Grains in the band: those with reference height in [z_low, z_high].
  std::size_t expected = 0;
  for (const BodyState& g : f.ref.bodies) expected += g.x.z() >= b.band.z_low && g.x.z() <= b.band.z_high;
  EXPECT_EQ(mask_count(b.mask), expected);
}

TEST(BandResult, NoBandWhileThePlateausDifferByLessThanATenthOfTheBoxDisplacement) {
  // The profile jumps by 0.05 mm, but the box moved 1 mm: no band.
  const Field f = ramp(0.05 * kMm);
  const BandResult b = band_result(f.now, f.ref, {0.0, 10 * kMm, 0.5 * kMm, 0.05, 20 * kMm});
  EXPECT_FALSE(b.band.found);
  EXPECT_EQ(mask_count(b.mask), 0u);
}

TEST(ShearSample, NaNBeforeShearAndBandLimitsOnceABandExists) {
  const Field f = ramp(1 * kMm);
  State not_yet;  // no reference: before shear
  const ShearSample before = shear_sample(f.now, not_yet, {0.0, 10 * kMm, 0.5 * kMm, 0.0, 20 * kMm});
  EXPECT_TRUE(std::isnan(before.rotation_mean_deg) && std::isnan(before.band_low_m) && std::isnan(before.fabric_psi));
  const ShearSample s = shear_sample(f.now, f.ref, {0.0, 10 * kMm, 0.5 * kMm, 0.05, 20 * kMm});
  EXPECT_EQ(s.rotation_mean_deg, 0.0);  // no grain turned
  EXPECT_EQ(s.rotation_band_deg, 0.0);
  EXPECT_EQ(s.coordination_number_band, 0.0);  // no contacts
  EXPECT_TRUE(std::isnan(s.fabric_psi));       // Psi of no contacts
  EXPECT_NEAR(s.band_low_m, 4.2 * kMm, 0.1 * kMm);
  EXPECT_NEAR(s.band_high_m, 5.8 * kMm, 0.1 * kMm);
}
