// The whole direct shear protocol on a tiny box (about 90 grains): preparation
// reaches its target density, consolidation holds the normal stress within
// 1 %, the cap holds it within 3 % during shear, and the measured F, N and
// displacements agree with the forces and motions of the walls.
#include "core/error.h"
#include "lab/direct_shear.h"
#include "tiny_box.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace grainlab;

namespace {

LabSpec tiny_protocol_spec() {
  LabSpec spec = testing_support::tiny_box_spec();
  spec.settings<ShearSpec>().final_strain = 0.02;
  return spec;
}

// One run shared by the tests below (it takes most of their time).
struct TinyRun {
  LabSpec spec = tiny_protocol_spec();
  DirectShearTest test{spec};
  double consolidated_stress = 0;  // Pa, when consolidation ended
  double max_shear_stress_error = 0;  // relative, at any step of shear
  double worst_force_balance = 0;  // |sum of wall forces along x| / N at the samples
  double worst_normal_balance = 0; // |sum of wall forces along z - W| / N at the samples
  double mean_force_balance = 0;   // the signed x balance averaged over the samples, then its magnitude

  TinyRun() {
    const Model& m = test.world().model;
    double weight = 0;
    for (const BodyModel& b : m.bodies) weight += b.gravity_mass * 9.81;
    std::size_t rows = 0, samples = 0;
    while (test.phase() != ShearPhase::Done) {
      const ShearPhase before = test.phase();
      test.advance(before == ShearPhase::Shear ? 1 : 500);
      if (before == ShearPhase::Consolidate && test.phase() == ShearPhase::Shear)
        consolidated_stress = test.normal_stress();
      if (test.phase() == ShearPhase::Shear) {
        const double sigma = spec.consolidation.normal_stress;
        max_shear_stress_error = std::max(max_shear_stress_error, std::abs(test.normal_stress() / sigma - 1));
      }
      if (test.series().size() != rows && test.phase() == ShearPhase::Shear) {
        rows = test.series().size();
        // Forces the grains put on the walls: with the grains nearly at
        // rest they sum to the grains' weight (the slabs' faces in the gap
        // carry some vertical load too, so the floor alone does not).
        Vec3 total = Vec3::Zero();
        for (const WallState& w : test.world().state.walls) total += w.force;
        const double x = std::abs(total.x()) / test.normal_force();
        const double z = std::abs(total.z() + weight) / test.normal_force();
        worst_force_balance = std::max(worst_force_balance, x);
        worst_normal_balance = std::max(worst_normal_balance, z);
        mean_force_balance += total.x() / test.normal_force();
        ++samples;
      }
    }
    mean_force_balance = std::abs(mean_force_balance) / std::max<std::size_t>(samples, 1);
  }
};

const TinyRun& tiny_run() {
  static const TinyRun run;
  return run;
}

constexpr int kStrain = 1, kDh = 2, kDv = 3, kF = 4, kN = 5, kSigma = 6, kRatio = 7, kPhi = 8;

}  // namespace

namespace {

// The four claims on the one tiny run: one test (ctest runs each test in its
// own process, so four tests would run the protocol four times, about 30 s
// each), a SCOPED_TRACE naming each claim.
void preparation_reaches_the_target_density(const TinyRun& r) {
  EXPECT_NEAR(r.test.achieved_void_ratio(), r.spec.target_void_ratio(), r.spec.specimen.tolerance);
  const auto& s = r.spec.specimen;
  EXPECT_NEAR(r.test.achieved_relative_density(), (s.e_max - r.test.achieved_void_ratio()) / (s.e_max - s.e_min),
              1e-12);
}

void consolidation_holds_the_normal_stress_within_one_percent(const TinyRun& r) {
  EXPECT_NEAR(r.consolidated_stress / r.spec.consolidation.normal_stress, 1.0, 0.01);
}

void cap_holds_the_normal_stress_within_three_percent_during_shear(const TinyRun& r) {
  // The record (every sample) within 3 %; single steps of a box with about
  // ten grains under the cap spike further as chains buckle. Measured on two
  // trajectories (the bits of an AVX-512 and of an AVX2 build): worst sample
  // under 2 % and 2.2 % (at the first sample, as the upper half starts at full
  // speed), worst single step 2.2 % and 5.4 %.
  std::printf("largest stress error during shear: %.2f %% at any step\n", 100 * r.max_shear_stress_error);
  EXPECT_LT(r.max_shear_stress_error, 0.08);
  for (const auto& row : r.test.series())
    EXPECT_NEAR(row[kSigma] / r.spec.consolidation.normal_stress, 1.0, 0.03) << "at strain " << row[kStrain];
}

void series_is_consistent_with_the_walls(const TinyRun& r) {
  const auto& rows = r.test.series();
  ASSERT_GE(rows.size(), 15u);  // 2 % strain sampled every 0.1 %
  const double L = r.spec.box.length, A = L * r.spec.box.width;
  for (const auto& row : rows) {
    EXPECT_DOUBLE_EQ(row[kDh], row[kStrain] * L);
    EXPECT_DOUBLE_EQ(row[kSigma], row[kN] / A);
    EXPECT_DOUBLE_EQ(row[kRatio], row[kF] / row[kN]);
    EXPECT_NEAR(row[kPhi], std::atan(row[kRatio]) * 180 / M_PI, 1e-9);
  }
  // The upper half moved at the shear speed; the last row is the final strain.
  EXPECT_NEAR(rows.back()[kStrain], r.spec.settings<ShearSpec>().final_strain, 1e-3);
  EXPECT_DOUBLE_EQ(rows.back()[kDv], r.test.cap_displacement());
  // Quasi-static: the shear force on the upper half is balanced by the lower
  // half, and the cap's load plus the weight by the floor and the slabs, up
  // to the grains' inertia (the x balance is taken against N, as F is small
  // at the first samples). In a box of about 90 grains one slip is a
  // transient of a few per cent of N at one sample, and which sample catches
  // one is chaotic in the contact's rounding: the worst x balance measured
  // 0.034 (session 8) and 0.056 (session 9, the same contact summed in
  // another order); z 0.002 at worst. The slips go both ways: with the
  // sharper 120-face grains of 2026-12-04 (generator_test.cpp,
  // AGrainOfFewFacesIs...) the samples swing by +-0.06 and the mean of
  // their magnitudes is 0.028, the signed mean 0.005. So the signed mean is
  // held to 2 % (a sustained imbalance: shearing too fast, or a wall force
  // not counted, which pushes one way) and every sample to 10 %.
  std::printf("wall force balance: x %.2g of N at worst, %.2g on average (signed); z %.2g of N at worst\n",
              r.worst_force_balance, r.mean_force_balance, r.worst_normal_balance);
  EXPECT_LT(r.mean_force_balance, 0.02);
  EXPECT_LT(r.worst_force_balance, 0.1);
  EXPECT_LT(r.worst_normal_balance, 0.05);
  // A dense specimen mobilises friction: the stress ratio rises well above 0.
  double peak = 0;
  for (const auto& row : rows) peak = std::max(peak, row[kRatio]);
  EXPECT_GT(peak, 0.3);
}

}  // namespace

TEST(DirectShearProtocol, TinyRunPreparesConsolidatesShearsAndBalances) {
  const TinyRun& r = tiny_run();
  {
    SCOPED_TRACE("the preparation reaches the target density");
    preparation_reaches_the_target_density(r);
  }
  {
    SCOPED_TRACE("consolidation holds the normal stress within 1 %");
    consolidation_holds_the_normal_stress_within_one_percent(r);
  }
  {
    SCOPED_TRACE("the cap holds the normal stress within 3 % during shear");
    cap_holds_the_normal_stress_within_three_percent_during_shear(r);
  }
  {
    SCOPED_TRACE("the series is consistent with the walls");
    series_is_consistent_with_the_walls(r);
  }
}

TEST(DirectShearProtocol, UnreachableTargetStopsWithAMessage) {
  LabSpec spec = tiny_protocol_spec();
  spec.specimen.void_ratio = 0.40;  // far denser than these grains pack
  DirectShearTest t(spec);
  try {
    while (t.phase() < ShearPhase::Consolidate) t.advance(1000);
    FAIL() << "preparation should have stopped";
  } catch (const RunError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("reached void ratio"), std::string::npos) << what;
    EXPECT_NE(what.find("0.400"), std::string::npos) << what;
  }
}
