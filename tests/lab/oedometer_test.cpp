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
using OC = OedometerColumn;

namespace {

// A row in oedometer_series_columns() order with the columns the summary reads.
std::vector<double> row(double target, double stress, double k0, double strain, double e, double modulus) {
  std::vector<double> r(oedometer_series_columns().size(), 0.0);
  r[OC::Target] = target, r[OC::Vertical] = stress, r[OC::K0] = k0, r[OC::Strain] = strain, r[OC::VoidRatio] = e, r[OC::Modulus] = modulus;
  return r;
}

// 240 beads in a 6 d_max box (5 x 5 x 4.2 mm), loose (e about 0.82 with the
// walls), consolidated at 50 kPa, then the schedule.
LabSpec bead_oedometer(std::vector<double> stresses, double wall_friction = 0) {
  LabSpec s = testing_support::loose_bead_spec("oedometer");
  s.material.wall_friction = wall_friction;
  s.settings<OedometerSpec>().stresses = std::move(stresses);
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
    const double m = rows.empty() ? NAN : (target - rows.back()[OC::Vertical]) / (eps - rows.back()[OC::Strain]);
    rows.push_back(row(target, target, 0.5, eps, e, m));
    rows.back()[OC::Stage] = static_cast<double>(rows.size() - 1);  // one row per stage
  };
  for (double s : {100e3, 200e3, 400e3, 800e3}) add(s, e0 - 0.05 * std::log10(s / 100e3));
  const double e800 = rows.back()[OC::VoidRatio];
  for (double s : {400e3, 200e3}) add(s, e800 + 0.01 * std::log10(800e3 / s));
  const OedometerSummary o = summarise_oedometer(rows);
  EXPECT_NEAR(o.compression_index, 0.05, 1e-12);
  EXPECT_NEAR(o.swelling_index, 0.01, 1e-12);
  EXPECT_EQ(o.max_stress, 800e3);
  EXPECT_NEAR(o.modulus_stress_exponent, 1.0 / 3.0, 1e-12);
  EXPECT_EQ(o.final_void_ratio, rows.back()[OC::VoidRatio]);
  // A constant-rate run's rows between the stages' ends change nothing:
  // the summary reads each stage's last row.
  std::vector<std::vector<double>> dense;
  for (const auto& r : rows) {
    std::vector<double> between = r;
    between[3] *= 0.97, between[9] += 0.003, between[10] = 1;  // on the way to the stage's stress
    dense.push_back(between);
    dense.push_back(r);
  }
  const OedometerSummary d = summarise_oedometer(dense);
  EXPECT_EQ(d.compression_index, o.compression_index);
  EXPECT_EQ(d.swelling_index, o.swelling_index);
  EXPECT_EQ(d.modulus_stress_exponent, o.modulus_stress_exponent);
  EXPECT_EQ(d.modulus_at_max_stress, o.modulus_at_max_stress);
  // No unloading: no Cs.
  rows.resize(4);
  EXPECT_TRUE(std::isnan(summarise_oedometer(rows).swelling_index));
}

TEST(Oedometer, FrictionlessRingOfBeads) {
  // Measured (seed 3, 240 beads, e 0.803 at 50 kPa): K0 0.67, 0.61, 0.57, 0.55
  // from 100 to 800 kPa, 0.93 and 1.08 unloading to 200 and 50 kPa (Mayne
  // and Kulhawy's (1 - sin phi) OCR^sin phi gives 0.9-1.1 there); M 32.2,
  // 36.1, 45.4, 60.1 MPa; Cc 0.040, Cs 0.022, n 0.37 (session 19, the
  // four-lane law: K0 0.63, 0.56, 0.54, 0.53, then 0.91 and 1.12; M 32.8,
  // 36.3, 44.6, 57.1 MPa; Cc 0.042, Cs 0.023, n 0.327).
  OedometerTest t(bead_oedometer({100e3, 200e3, 400e3, 800e3, 200e3, 50e3}));
  run_to_end(t);
  const auto& rows = t.series();
  for (const auto& r : rows)
    std::printf("stage %g: sigma_v/target %.5f, floor/cap %.5f, K0 %.4f, e %.5f, M %.4g Pa\n", r[OC::Stage], r[OC::Vertical] / r[OC::Target],
                r[OC::FloorStress] / r[OC::Vertical], r[OC::K0], r[OC::VoidRatio], r[OC::Modulus]);
  ASSERT_EQ(rows.size(), 7u);
  const double e0 = rows[0][OC::VoidRatio], h0 = rows[0][OC::Height];
  for (std::size_t i = 0; i < rows.size(); ++i) {
    SCOPED_TRACE(i);
    const auto& r = rows[i];
    EXPECT_EQ(r[OC::Stage], static_cast<double>(i));
    // The servo held the stage's stress within 1 %.
    EXPECT_NEAR(r[OC::Vertical] / r[OC::Target], 1.0, 0.01);
    // Frictionless walls carry no vertical load: the floor sees the cap's stress.
    EXPECT_NEAR(r[OC::FloorStress] / r[OC::Vertical], 1.0, 0.01);
    // Strain, height and void ratio agree: (e0 - e) / (1 + e0) = eps = 1 - H / H0.
    EXPECT_NEAR(r[OC::Strain], 1 - r[OC::Height] / h0, 1e-12);
    EXPECT_NEAR((e0 - r[OC::VoidRatio]) / (1 + e0), r[OC::Strain], 1e-12);
  }
  // K0 of the normally consolidated specimen (stresses at least 4 x the
  // consolidation's: its first stages remember the preparation) in [0.3, 0.7].
  for (std::size_t i = 2; i <= 4; ++i) {
    EXPECT_GT(rows[i][OC::K0], 0.3) << i;
    EXPECT_LT(rows[i][OC::K0], 0.7) << i;
  }
  // Unloading locks lateral stress in: K0 at 200 kPa is higher after 800 kPa.
  EXPECT_GT(rows[5][OC::K0], rows[2][OC::K0]);
  // Loading compresses, unloading swells back less than it compressed.
  for (std::size_t i = 1; i <= 4; ++i) EXPECT_LT(rows[i][OC::VoidRatio], rows[i - 1][OC::VoidRatio]) << i;
  EXPECT_GT(rows[5][OC::VoidRatio], rows[4][OC::VoidRatio]);
  EXPECT_LT(rows[6][OC::VoidRatio], rows[0][OC::VoidRatio]);
  const OedometerSummary o = summarise_oedometer(rows);
  std::printf("Cc %.4f, Cs %.4f, n %.3f\n", o.compression_index, o.swelling_index, o.modulus_stress_exponent);
  EXPECT_GT(o.compression_index, 0);
  EXPECT_GT(o.swelling_index, 0);
  EXPECT_LT(o.swelling_index, o.compression_index);
  // Hertz spheres: M ~ s^n with n = 1/3 for a fixed contact network
  // (effective-medium theory), more as contacts form under load. Fitted
  // from the second increment on (oedometer.h). One specimen of 240 beads
  // is too few to judge it: with the same code, seeds 3, 5, 6 and 7 gave
  // 0.327, 0.376, 0.370 and 0.348 (session 19; seed 3 gave 0.37 before the
  // four-lane contact law moved its roundings; seed 4's compaction does not
  // come to rest, the spinning bead of sphere_box.h). So the exponent is the
  // mean over seeds 3, 5 and 6.
  double n_sum = o.modulus_stress_exponent;
  for (int seed : {5, 6}) {
    LabSpec spec = bead_oedometer({100e3, 200e3, 400e3, 800e3, 200e3, 50e3});
    spec.seed = seed;
    OedometerTest other(spec);
    run_to_end(other);
    const double n = summarise_oedometer(other.series()).modulus_stress_exponent;
    std::printf("seed %d: n %.3f\n", seed, n);
    n_sum += n;
  }
  const double n_mean = n_sum / 3;
  std::printf("n over seeds 3, 5, 6: %.3f\n", n_mean);
  EXPECT_GT(n_mean, 1.0 / 3.0);
  EXPECT_LT(n_mean, 2.0 / 3.0);
}

TEST(Oedometer, WallFrictionCarriesPartOfTheLoad) {
  // Janssen: side walls with friction hold part of the cap's load, so the
  // floor sees less. Measured: 0.838 of the cap's stress (frictionless walls:
  // 0.999-1.002); the wall contacts' friction is min(0.3, grain 0.19).
  // Janssen's bound, the friction fully mobilised on all four walls:
  // d sigma_v / dz = -4 mu_w K sigma_v / L, so floor / cap >= exp(-4 mu_w K
  // H / L), with K = sigma_h over the mean of the cap's and floor's stresses.
  const LabSpec spec = bead_oedometer({400e3}, 0.3);
  OedometerTest t(spec);
  run_to_end(t);
  const auto& r = t.series().back();
  const double k = r[OC::Lateral] / (0.5 * (r[OC::Vertical] + r[OC::FloorStress]));
  const double janssen = std::exp(-4 * 0.19 * k * r[OC::Height] / spec.box.length);
  std::printf("floor / cap stress with wall friction 0.3 at 400 kPa: %.4f (Janssen's bound %.4f, K %.3f)\n",
              r[OC::FloorStress] / r[OC::Vertical], janssen, k);
  EXPECT_NEAR(r[OC::Vertical] / 400e3, 1.0, 0.01);
  EXPECT_LT(r[OC::FloorStress] / r[OC::Vertical], 0.99);
  EXPECT_GT(r[OC::FloorStress] / r[OC::Vertical], janssen);
}

TEST(Oedometer, StagesAndTheirStresses) {
  LabSpec s = bead_oedometer({400e3});
  OedometerTest t(s);
  EXPECT_EQ(t.stages(), 1);
  EXPECT_EQ(t.stage_stress(0), 50e3);
  EXPECT_EQ(t.stage_stress(1), 400e3);
  EXPECT_EQ(t.progress(), 0.0);
  EXPECT_EQ(t.phase_name(), "deposit");
}

TEST(Oedometer, ConstantRateOfStrainFollowsTheStagedCurve) {
  // The same specimen loaded 50 -> 200 -> 400 kPa and unloaded to 100 kPa,
  // once in stages held to rest and once at a constant rate of strain
  // (I = 9e-4 at 50 kPa, less above; the stages' servo moves the cap no
  // faster): a dry sand has no consolidation time, so at a quasi-static rate
  // both give the same e-log sigma curve. Measured (seed 3): e 0.79537 /
  // 0.79517 at 200 kPa, 0.78740 / 0.78725 at 400, 0.79793 / 0.79812 back at
  // 100 kPa (constant rate / stages); K0 0.590 / 0.608, 0.565 / 0.574,
  // 1.025 / 0.984; Cc 0.0264 / 0.0263. (With the stages' servo at the
  // preparation's speed limit, about 1000 times faster, K0 was 0.68 at
  // 200 kPa and 0.74 back at 100 kPa: a sudden load or release rearranges
  // the grains.)
  const std::vector<double> schedule = {200e3, 400e3, 100e3};
  OedometerTest staged(bead_oedometer(schedule));
  run_to_end(staged);
  LabSpec s = bead_oedometer(schedule);
  s.settings<OedometerSpec>().loading = "constant-rate";
  OedometerTest rate(s);
  run_to_end(rate);
  ASSERT_TRUE(rate.constant_rate());
  const auto& rows = rate.series();
  const auto& steps = staged.series();
  ASSERT_EQ(steps.size(), 4u);
  ASSERT_GT(rows.size(), 20u);  // 50 rows per decade of stress
  // Each stage's last row is where the cap stress reached the stage's stress.
  std::vector<std::vector<double>> ends;
  for (std::size_t i = 0; i < rows.size(); ++i)
    if (i + 1 == rows.size() || rows[i + 1][OC::Stage] != rows[i][OC::Stage]) ends.push_back(rows[i]);
  ASSERT_EQ(ends.size(), 4u);
  const double h0 = rows[0][OC::Height], e0 = rows[0][OC::VoidRatio], t0 = rows[0][OC::Time], v = rate.cap_speed();
  EXPECT_EQ(rows[0][OC::VoidRatio], steps[0][OC::VoidRatio]);  // the same consolidated specimen
  for (std::size_t i = 0; i < rows.size(); ++i) {
    SCOPED_TRACE(i);
    const auto& r = rows[i];
    if (i > 0) {
      EXPECT_GE(r[OC::Stage], rows[i - 1][OC::Stage]);
    }
    EXPECT_NEAR(r[OC::Strain], 1 - r[OC::Height] / h0, 1e-12);
    EXPECT_NEAR((e0 - r[OC::VoidRatio]) / (1 + e0), r[OC::Strain], 1e-12);
    // Loading: the cap comes down at the constant speed.
    if (r[OC::Stage] <= 2) {
      EXPECT_NEAR(h0 - r[OC::Height], v * (r[OC::Time] - t0), 1e-9 * h0);
    }
  }
  for (std::size_t k = 1; k < ends.size(); ++k) {
    SCOPED_TRACE(k);
    const double target = ends[k][OC::Target], sv = ends[k][OC::Vertical];
    std::printf("stage %zu: sigma_v/target %.4f; e %.5f at a constant rate, %.5f in stages; K0 %.3f, %.3f\n", k,
                sv / target, ends[k][OC::VoidRatio], steps[k][OC::VoidRatio], ends[k][OC::K0], steps[k][OC::K0]);
    if (k < 3) {
      EXPECT_GE(sv, target);  // loading: reached from below
    } else {
      EXPECT_LE(sv, target);  // unloading: from above
    }
    EXPECT_NEAR(sv / target, 1.0, 0.03);
    EXPECT_NEAR(ends[k][OC::VoidRatio], steps[k][OC::VoidRatio], 0.05 * (e0 - steps[2][OC::VoidRatio]));  // 5 % of the compression
    // K0: the stages' rests (creep at a constant sigma_v) move it a little,
    // most on unloading, where the lateral stress is locked in.
    EXPECT_NEAR(ends[k][OC::K0], steps[k][OC::K0], k < 3 ? 0.05 : 0.1);
  }
  const OedometerSummary a = summarise_oedometer(rows), b = summarise_oedometer(steps);
  std::printf("Cc %.4f / %.4f, Cs %.4f / %.4f, n %.3f / %.3f (constant rate / stages)\n", a.compression_index,
              b.compression_index, a.swelling_index, b.swelling_index, a.modulus_stress_exponent,
              b.modulus_stress_exponent);
  EXPECT_NEAR(a.compression_index, b.compression_index, 0.1 * b.compression_index);
  EXPECT_GT(a.swelling_index, 0);
  EXPECT_LT(a.swelling_index, a.compression_index);
}
