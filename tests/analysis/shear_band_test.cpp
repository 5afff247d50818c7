// Displacement profile and shear band on synthetic displacement fields with a
// known band.
#include "analysis/shear_band.h"
#include "core/rng.h"
#include "displacement_field.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>

using namespace grainlab;
using namespace grainlab::analysis;

namespace {

using analysis_test::Field;
using analysis_test::kMm;

// 4000 grains evenly spread in reference height over [-10, 10] mm (100 per
// 0.5 mm layer, symmetric about each layer centre), scattered in x and y,
// displaced along x by u(z) plus optional noise.
Field make_field(const std::function<double(double)>& u, double noise = 0, std::uint64_t seed = 1) {
  Rng rng(seed);
  Field f;
  const int n = 4000;
  f.ref.bodies.resize(n);
  f.now.bodies.resize(n);
  for (int i = 0; i < n; ++i) {
    const double z = -10 * kMm + (i + 0.5) * (20 * kMm / n);
    f.ref.bodies[i].x = Vec3(rng.uniform(-20, 20) * kMm, rng.uniform(-20, 20) * kMm, z);
    f.now.bodies[i].x = f.ref.bodies[i].x + Vec3(u(z) + noise * rng.normal(), 0.3 * noise * rng.normal(), 0);
  }
  return f;
}

ProfileSpec forty_layers() {
  ProfileSpec spec;
  spec.layers = 40;
  spec.z_min = -10 * kMm;
  spec.z_max = 10 * kMm;
  return spec;
}

}  // namespace

TEST(ShearBand, ProfileOfAUniformShiftIsFlat) {
  const Field f = make_field([](double) { return 2 * kMm; });
  const DisplacementProfile p = displacement_profile(f.now, f.ref);  // range from the grains
  ASSERT_EQ(p.u.size(), 20u);
  EXPECT_NEAR(p.z_min, f.ref.bodies.front().x.z(), 1e-15);
  EXPECT_NEAR(p.z_max, f.ref.bodies.back().x.z(), 1e-15);
  Index total = 0;
  for (std::size_t k = 0; k < p.u.size(); ++k) {
    EXPECT_NEAR(p.u[k], 2 * kMm, 1e-15);
    total += p.count[k];
  }
  EXPECT_EQ(total, 4000);  // the top grain is in the last layer
  EXPECT_FALSE(find_shear_band(p).found);  // nothing sheared
}

TEST(ShearBand, LinearRampBetweenPlateaus) {
  // u = 0 below -2 mm, d above 3 mm, linear between: U = 0.1 at -1.5 mm, 0.9 at 2.5 mm.
  const double d = 5 * kMm, z1 = -2 * kMm, z2 = 3 * kMm;
  const auto u = [&](double z) { return d * std::clamp((z - z1) / (z2 - z1), 0.0, 1.0); };
  const Field f = make_field(u);
  const DisplacementProfile p = displacement_profile(f.now, f.ref, forty_layers());
  const ShearBand b = find_shear_band(p);
  std::printf("  ramp: band [%.4f, %.4f] mm (exact [-1.5, 2.5]), mid %.4f mm\n", b.z_low / kMm, b.z_high / kMm,
              b.z_mid / kMm);
  ASSERT_TRUE(b.found);
  EXPECT_NEAR(b.u_bottom, 0.0, 1e-12);
  EXPECT_NEAR(b.u_top, d, 1e-12);
  EXPECT_NEAR(b.z_low, -1.5 * kMm, 1e-9);
  EXPECT_NEAR(b.z_high, 2.5 * kMm, 1e-9);
  EXPECT_NEAR(b.z_mid, 0.5 * kMm, 1e-9);
  // Grains selected by reference height: the 4 mm of 20 hold a fifth of them.
  const GrainMask band = grains_in_band(f.ref, b);
  EXPECT_EQ(mask_count(band), 800u);
}

TEST(ShearBand, TanhProfileWithNoiseAndAGlitchInAPlateau) {
  // u = (d/2)(1 + tanh((z - z0)/w)): the band is z0 -+ w atanh(0.8).
  const double d = 4 * kMm, z0 = 1 * kMm, w = 1.5 * kMm;
  const auto u = [&](double z) { return 0.5 * d * (1 + std::tanh((z - z0) / w)); };
  Field f = make_field(u, 0.02 * d, 3);
  // A few grains near the bottom dragged along (U ~ 0.3 in their layer): the
  // band must not grow down to them.
  for (int i = 20; i < 60; ++i) f.now.bodies[i].x.x() += 0.6 * d;
  const ShearBand b = find_shear_band(displacement_profile(f.now, f.ref, forty_layers()));
  const double half = w * std::atanh(0.8);
  std::printf("  tanh: band [%.4f, %.4f] mm (exact [%.4f, %.4f])\n", b.z_low / kMm, b.z_high / kMm,
              (z0 - half) / kMm, (z0 + half) / kMm);
  ASSERT_TRUE(b.found);
  const double layer = 0.5 * kMm;
  // Interpolating tanh between layer centres and the noise (0.2 % of d per
  // layer) each move the limits by a few hundredths of a millimetre.
  EXPECT_NEAR(b.z_low, z0 - half, 0.2 * layer);
  EXPECT_NEAR(b.z_high, z0 + half, 0.2 * layer);
  EXPECT_NEAR(b.z_mid, z0, 0.2 * layer);
}

TEST(ShearBand, ShearAgainstTheMeasuredDirectionFindsTheSameBand) {
  const auto u = [](double z) { return -3 * kMm * std::clamp((z + 2 * kMm) / (5 * kMm), 0.0, 1.0); };
  const Field f = make_field(u);
  const ShearBand b = find_shear_band(displacement_profile(f.now, f.ref, forty_layers()));
  ASSERT_TRUE(b.found);
  EXPECT_NEAR(b.z_low, -1.5 * kMm, 1e-9);
  EXPECT_NEAR(b.z_high, 2.5 * kMm, 1e-9);
  EXPECT_LT(b.u_top, b.u_bottom);
}

TEST(ShearBand, EmptyLayersAreSkipped) {
  // Only grains below -4 mm and above 4 mm: the middle layers are empty and
  // the band spans the gap, interpolated across it.
  const auto u = [](double z) { return z > 0 ? 2 * kMm : 0.0; };
  Field f = make_field(u);
  State ref, now;
  for (std::size_t i = 0; i < f.ref.bodies.size(); ++i) {
    if (std::abs(f.ref.bodies[i].x.z()) < 4 * kMm) continue;
    ref.bodies.push_back(f.ref.bodies[i]);
    now.bodies.push_back(f.now.bodies[i]);
  }
  const DisplacementProfile p = displacement_profile(now, ref, forty_layers());
  EXPECT_TRUE(std::isnan(p.u[20]));
  EXPECT_EQ(p.count[20], 0);
  const ShearBand b = find_shear_band(p);
  ASSERT_TRUE(b.found);
  // Across the gap, from the layer centred at -4.25 mm (U = 0) to 4.25 mm (U = 1).
  EXPECT_NEAR(b.z_low, -4.25 * kMm + 0.1 * 8.5 * kMm, 1e-9);
  EXPECT_NEAR(b.z_high, -4.25 * kMm + 0.9 * 8.5 * kMm, 1e-9);
}
