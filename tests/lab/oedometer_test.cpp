// The oedometer (lab/oedometer.h): its summary against rows built from known
// laws, and a small oedometer of glass beads (spheres: cheap) checked for
// what the physics and the protocol require.
#include "core/error.h"
#include "lab/oedometer.h"
#include "sphere_box.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

using namespace grainlab;

namespace {

// A row in oedometer_series_columns() order with the columns the summary reads.
std::vector<double> row(double target, double stress, double k0, double strain, double e, double modulus) {
  std::vector<double> r(oedometer_series_columns().size(), 0.0);
  r[2] = target, r[3] = stress, r[6] = k0, r[7] = strain, r[9] = e, r[10] = modulus;
  return r;
}

// 240 beads in a 6 d_max box (5 x 5 x 4.2 mm), loose (e about 0.82 with the
// walls), consolidated at 50 kPa, then the schedule.
DirectShearSpec bead_oedometer(std::vector<double> stresses, double wall_friction = 0) {
  DirectShearSpec s = testing_support::loose_bead_spec("oedometer");
  s.material.wall_friction = wall_friction;
  s.oedometer.stresses = std::move(stresses);
  return s;
}

void run_to_end(OedometerTest& t) {
  while (t.advance(1000)) {
  }
  ASSERT_TRUE(t.done());
}

}  // namespace

TEST(Oedometer, SummaryOfAKnownCompressionLaw) {
  // Loading 100 -> 800 kPa on e = e0 - 0.05 log10(s / 100 kPa) (Cc = 0.05),
  // strain eps = c s^(2/3) (Hertz: the secant modulus of a doubling is then
  // exactly proportional to s^(1/3)), unloading 800 -> 200 kPa on
  // e = e(800) + 0.01 log10(800 kPa / s) (Cs = 0.01).
  const double e0 = 0.8, c = 1e-6;
  std::vector<std::vector<double>> rows;
  const auto add = [&](double target, double e) {
    const double eps = c * std::pow(target, 2.0 / 3.0);
    const double m = rows.empty() ? NAN : (target - rows.back()[3]) / (eps - rows.back()[7]);
    rows.push_back(row(target, target, 0.5, eps, e, m));
  };
  for (double s : {100e3, 200e3, 400e3, 800e3}) add(s, e0 - 0.05 * std::log10(s / 100e3));
  const double e800 = rows.back()[9];
  for (double s : {400e3, 200e3}) add(s, e800 + 0.01 * std::log10(800e3 / s));
  const OedometerSummary o = summarise_oedometer(rows);
  EXPECT_NEAR(o.compression_index, 0.05, 1e-12);
  EXPECT_NEAR(o.swelling_index, 0.01, 1e-12);
  EXPECT_EQ(o.max_stress, 800e3);
  EXPECT_NEAR(o.modulus_stress_exponent, 1.0 / 3.0, 1e-12);
  EXPECT_EQ(o.final_void_ratio, rows.back()[9]);
  // No unloading: no Cs.
  rows.resize(4);
  EXPECT_TRUE(std::isnan(summarise_oedometer(rows).swelling_index));
}

TEST(Oedometer, FrictionlessRingOfBeads) {
  // Measured (seed 3, 240 beads, e 0.803 at 50 kPa): K0 0.70, 0.65, 0.62, 0.59
  // from 100 to 800 kPa, 0.68 and 0.84 unloading to 200 and 50 kPa; M 30.0,
  // 34.4, 43.8, 57.9 MPa.
  OedometerTest t(bead_oedometer({100e3, 200e3, 400e3, 800e3, 200e3, 50e3}));
  run_to_end(t);
  const auto& rows = t.series();
  for (const auto& r : rows)
    std::printf("stage %g: sigma_v/target %.5f, floor/cap %.5f, K0 %.4f, e %.5f, M %.4g Pa\n", r[1], r[3] / r[2],
                r[4] / r[3], r[6], r[9], r[10]);
  ASSERT_EQ(rows.size(), 7u);
  const double e0 = rows[0][9], h0 = rows[0][8];
  for (std::size_t i = 0; i < rows.size(); ++i) {
    SCOPED_TRACE(i);
    const auto& r = rows[i];
    EXPECT_EQ(r[1], static_cast<double>(i));
    // The servo held the stage's stress within 1 %.
    EXPECT_NEAR(r[3] / r[2], 1.0, 0.01);
    // Frictionless walls carry no vertical load: the floor sees the cap's stress.
    EXPECT_NEAR(r[4] / r[3], 1.0, 0.01);
    // Strain, height and void ratio agree: (e0 - e) / (1 + e0) = eps = 1 - H / H0.
    EXPECT_NEAR(r[7], 1 - r[8] / h0, 1e-12);
    EXPECT_NEAR((e0 - r[9]) / (1 + e0), r[7], 1e-12);
  }
  // K0 of the normally consolidated specimen (stresses at least 4 x the
  // consolidation's: its first stages remember the preparation) in [0.3, 0.7].
  for (std::size_t i = 2; i <= 4; ++i) {
    EXPECT_GT(rows[i][6], 0.3) << i;
    EXPECT_LT(rows[i][6], 0.7) << i;
  }
  // Unloading locks lateral stress in: K0 at 200 kPa is higher after 800 kPa.
  EXPECT_GT(rows[5][6], rows[2][6]);
  // Loading compresses, unloading swells back less than it compressed.
  for (std::size_t i = 1; i <= 4; ++i) EXPECT_LT(rows[i][9], rows[i - 1][9]) << i;
  EXPECT_GT(rows[5][9], rows[4][9]);
  EXPECT_LT(rows[6][9], rows[0][9]);
  const OedometerSummary o = summarise_oedometer(rows);
  std::printf("Cc %.4f, Cs %.4f, n %.3f\n", o.compression_index, o.swelling_index, o.modulus_stress_exponent);
  EXPECT_GT(o.compression_index, 0);
  EXPECT_GT(o.swelling_index, 0);
  EXPECT_LT(o.swelling_index, o.compression_index);
  // Hertz spheres: M ~ s^n with n = 1/3 for a fixed contact network
  // (effective-medium theory), more as contacts form under load. Fitted
  // from the second increment on (oedometer.h), measured 0.37 here.
  EXPECT_GT(o.modulus_stress_exponent, 1.0 / 3.0);
  EXPECT_LT(o.modulus_stress_exponent, 2.0 / 3.0);
}

TEST(Oedometer, WallFrictionCarriesPartOfTheLoad) {
  // Janssen: side walls with friction hold part of the cap's load, so the
  // floor sees less. Measured: 0.984 of the cap's stress (frictionless walls:
  // 0.999-1.002); the wall contacts' friction is min(0.3, grain 0.19).
  OedometerTest t(bead_oedometer({400e3}, 0.3));
  run_to_end(t);
  const auto& r = t.series().back();
  std::printf("floor / cap stress with wall friction 0.3 at 400 kPa: %.4f\n", r[4] / r[3]);
  EXPECT_NEAR(r[3] / 400e3, 1.0, 0.01);
  EXPECT_LT(r[4] / r[3], 0.99);
  EXPECT_GT(r[4] / r[3], 0.5);
}

TEST(Oedometer, StagesAndTheirStresses) {
  DirectShearSpec s = bead_oedometer({400e3});
  OedometerTest t(s);
  EXPECT_EQ(t.stages(), 1);
  EXPECT_EQ(t.stage_stress(0), 50e3);
  EXPECT_EQ(t.stage_stress(1), 400e3);
  EXPECT_EQ(t.progress(), 0.0);
  EXPECT_EQ(t.phase_name(), "deposit");
}
