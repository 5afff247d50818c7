// The drained triaxial test (lab/triaxial.h): its summary against rows built
// from known curves, and a small triaxial of glass beads (spheres: cheap)
// checked for its identities and its servos.
#include "lab/triaxial.h"
#include "sphere_box.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <iterator>
#include <numbers>
#include <vector>

using namespace grainlab;
using TC = TriaxialColumn;

namespace {

// A row in triaxial_series_columns() order with the columns the summary reads.
std::vector<double> row(double eps_a, double eps_v, double q, double p, double e) {
  std::vector<double> r(triaxial_series_columns().size(), 0.0);
  r[TC::AxialStrain] = eps_a, r[TC::VolumetricStrain] = eps_v, r[TC::Deviator] = q, r[TC::Mean] = p, r[TC::Ratio] = q / p, r[TC::VoidRatio] = e;
  return r;
}

double deg(double rad) { return rad * 180 / std::numbers::pi; }

}  // namespace

TEST(Triaxial, SummaryOfKnownCurves) {
  // q rises linearly to 120 kPa at 2 % (E50 = 60 kPa / 1 % = 6 MPa), then
  // eta = 1.2 flat to 4 % and 0.9 from 6 % on; eps_v contracts at rate 0.5
  // to 1 %, then dilates at r = -0.5 (sin psi = 0.5 / 2.5 = 0.2).
  std::vector<std::vector<double>> rows;
  for (int i = 0; i <= 100; ++i) {
    const double ea = 0.001 * i;
    const double eta = ea <= 0.04 ? 1.2 * std::min(1.0, ea / 0.02) : ea < 0.06 ? 1.2 - 0.3 * (ea - 0.04) / 0.02 : 0.9;
    const double p = 100e3, q = eta * p;
    const double ev = ea <= 0.01 ? 0.5 * ea : 0.005 - 0.5 * (ea - 0.01);
    rows.push_back(row(ea, ev, ea == 0 ? 1e-9 : q, p, 0.7 - ev));
  }
  const TriaxialSummary s = summarise_triaxial(rows);
  EXPECT_NEAR(s.peak_stress_ratio, 1.2, 1e-12);
  EXPECT_NEAR(s.peak_friction_angle_deg, deg(std::asin(3 * 1.2 / 7.2)), 1e-9);  // 30 deg
  EXPECT_NEAR(s.critical_stress_ratio, 0.9, 1e-12);
  EXPECT_NEAR(s.critical_friction_angle_deg, deg(std::asin(2.7 / 6.9)), 1e-9);
  EXPECT_NEAR(s.peak_dilatancy_angle_deg, deg(std::asin(0.2)), 1e-9);
  // Still dilating at r = -0.5 over the last fifth: not a critical state.
  EXPECT_NEAR(s.critical_dilatancy_angle_deg, deg(std::asin(0.2)), 1e-9);
  EXPECT_NEAR(s.e50_Pa, 60e3 / 0.01, 1e-3);  // half of q_peak = 120 kPa is 60 kPa, reached at 1 %
  EXPECT_GE(s.strain_at_peak, 0.02 - 1e-12);
  EXPECT_LE(s.strain_at_peak, 0.04 + 1e-12);
}

TEST(Triaxial, DilatancyOverTheLastFifthIsZeroOnlyAtConstantVolume) {
  // eps_v dilates at r = -0.3 to 12 %, then stays constant to 20 %: the
  // last fifth (16-20 %) is at constant volume, psi there 0; a run stopped
  // at 12 % is still dilating there, psi = asin(0.3 / 2.3).
  std::vector<std::vector<double>> rows;
  for (int i = 0; i <= 200; ++i) {
    const double ea = 0.001 * i;
    const double ev = -0.3 * std::min(ea, 0.12);
    rows.push_back(row(ea, ev, ea == 0 ? 1e-9 : 100e3, 100e3, 0.7));
  }
  EXPECT_NEAR(summarise_triaxial(rows).critical_dilatancy_angle_deg, 0.0, 1e-9);
  rows.resize(121);
  EXPECT_NEAR(summarise_triaxial(rows).critical_dilatancy_angle_deg, deg(std::asin(0.3 / 2.3)), 1e-9);
}

TEST(Triaxial, BeadsHoldTheCellPressureAndTheIdentities) {
  // 240 beads, 6 d_max square, loose (e 0.80), sigma_3 50 kPa, to 4 % axial
  // strain. Measured (seed 3): side stress error of the interval means
  // 0.0016 on average over the samples and 0.0034 at worst (with the cap's
  // gain 0.05 on the sides as well: 0.0077 and 0.030).
  LabSpec spec = testing_support::loose_bead_spec("triaxial");
  spec.settings<TriaxialSpec>().final_strain = 0.04;
  spec.output.strain_interval = 0.002;
  TriaxialTest t(spec);
  while (t.advance(1000)) {
  }
  ASSERT_TRUE(t.done());
  const auto& rows = t.series();
  ASSERT_GE(rows.size(), 20u);
  // The isotropic state: all five walls at sigma_3 within the tolerance.
  EXPECT_NEAR(rows[0][TC::Sigma1] / 50e3, 1.0, 0.01);
  EXPECT_NEAR(rows[0][TC::Sigma3] / 50e3, 1.0, 0.01);
  EXPECT_NEAR(rows[0][TC::AxialStrain], 0.0, 1e-15);
  const double e0 = rows[0][TC::VoidRatio], t0 = rows[0][TC::Time];
  double mean_error = 0, worst_error = 0;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    SCOPED_TRACE(i);
    const auto& r = rows[i];
    EXPECT_NEAR(r[TC::Deviator], r[TC::Sigma1] - r[TC::Sigma3], 1e-9 * r[TC::Sigma1]);                 // q = sigma_1 - sigma_3
    EXPECT_NEAR(r[TC::Mean], (r[TC::Sigma1] + 2 * r[TC::Sigma3]) / 3, 1e-9 * r[TC::Sigma1]);       // p' = (sigma_1 + 2 sigma_3) / 3
    EXPECT_NEAR((e0 - r[TC::VoidRatio]) / (1 + e0), r[TC::VolumetricStrain], 1e-12);            // eps_v from the walls = from e
    EXPECT_GT(r[TC::AxialStrain], rows[i - 1][TC::AxialStrain]);
    mean_error += r[TC::SideError] / (rows.size() - 1);
    worst_error = std::max(worst_error, r[TC::SideError]);
    EXPECT_LT(r[TC::SideError], 0.01);  // sigma_3 held within 1 % on every side at every sample
    EXPECT_GT(r[TC::Ratio], 0.0);  // compression: sigma_1 > sigma_3
  }
  // The cap moves at a constant speed: eps_a grows linearly in time.
  const double rate = rows.back()[TC::AxialStrain] / (rows.back()[TC::Time] - t0);  // axial strain per second
  EXPECT_NEAR(rate * (rows[10][TC::Time] - t0), rows[10][TC::AxialStrain], 1e-9);
  std::printf("side stress error: mean %.4f, worst %.4f\n", mean_error, worst_error);
  const TriaxialSummary s = summarise_triaxial(rows);
  EXPECT_GT(s.peak_friction_angle_deg, 10);
  EXPECT_LT(s.peak_friction_angle_deg, 45);
  EXPECT_GT(s.e50_Pa, 0);
}

namespace {

// The mean of column `c` over the last fifth of the axial strain (the
// summary's critical-state window).
double last_fifth_mean(const std::vector<std::vector<double>>& rows, int c) {
  double sum = 0;
  int n = 0;
  for (const auto& r : rows)
    if (r[TC::AxialStrain] >= 0.8 * rows.back()[TC::AxialStrain]) sum += r[c], ++n;
  return sum / n;
}

std::vector<std::vector<double>> bead_triaxial(double deposition_friction, double void_ratio, int seed = 3) {
  // 8 d_max square (6.7 mm), 5.1 mm high, sigma_3 50 kPa, to 35 % at I =
  // 4.5e-3 (5 times the default, for test time: both specimens alike). At
  // 6 d_max high (5.05 mm) the loose specimen's compaction once never came
  // to rest: a rattling bead spun at 412 rad/s on four barely loaded
  // contacts, which point contacts without twisting friction cannot stop;
  // the rest test now leaves such a spin out (lab/rest_criteria.h).
  LabSpec s = testing_support::sphere_spec(8);
  s.seed = seed;
  s.test = "triaxial";
  s.box.height = 5.1e-3;
  s.specimen.void_ratio = void_ratio;
  s.specimen.tolerance = 0.2;  // the deposition friction decides
  s.specimen.deposition_friction = deposition_friction;
  s.consolidation.normal_stress = 50e3;
  s.numerics.inertial_number = 4.5e-3;
  s.settings<TriaxialSpec>().final_strain = 0.35;
  s.output.strain_interval = 0.002;
  TriaxialTest t(s);
  while (t.advance(1000)) {
  }
  EXPECT_TRUE(t.done());
  return t.series();
}

}  // namespace

// What a kind of specimen does, as the mean over five seeds: one specimen
// of 240 beads is one realisation, and its end state moves with any change
// to the rounding (a one-ulp change to the sphere-sphere normal moved this
// test's single-seed q/p' comparison from 7 % to 12 % apart; one specimen's
// critical q/p' scatters by about 0.04, so means of three a side still came
// 11.6 % apart on another rounding).
struct BeadMean {
  double e0 = 0, e_cs = 0, eta_cs = 0, eta_peak = 0;
};

BeadMean bead_mean(double deposition_friction, double void_ratio) {
  BeadMean m;
  constexpr int kSeeds[] = {3, 4, 5, 6, 7};
  for (int seed : kSeeds) {
    const auto rows = bead_triaxial(deposition_friction, void_ratio, seed);
    EXPECT_GT(rows.size(), 100u);
    if (rows.empty()) continue;
    const TriaxialSummary s = summarise_triaxial(rows);
    constexpr double w = 1.0 / std::size(kSeeds);
    m.e0 += w * rows[0][TC::VoidRatio], m.e_cs += w * last_fifth_mean(rows, TC::VoidRatio);
    m.eta_cs += w * s.critical_stress_ratio, m.eta_peak += w * s.peak_stress_ratio;
    std::printf("friction %.1f seed %d: e at shear %.4f, over the last fifth %.4f; q/p' peak %.4f, critical %.4f\n",
                deposition_friction, seed, rows[0][TC::VoidRatio], last_fifth_mean(rows, TC::VoidRatio),
                s.peak_stress_ratio, s.critical_stress_ratio);
  }
  return m;
}

TEST(Triaxial, LooseAndDenseBeadsReachOneCriticalState) {
  // The same beads deposited with friction 1.0 (loose) and 0 (dense), five
  // specimens each. Measured (seed 3, before the means): e 0.821 and 0.718
  // after isotropic consolidation; over the last fifth e 0.815 and 0.813,
  // q/p' 0.595 and 0.616 (phi_cs 15.6 and 16.1 deg; rigid frictionless
  // walls, mu 0.19).
  const BeadMean loose = bead_mean(1.0, 0.85), dense = bead_mean(0.0, 0.60);
  std::printf("means: e at shear %.4f / %.4f, over the last fifth %.4f / %.4f; critical q/p' %.4f / %.4f (loose / dense)\n",
              loose.e0, dense.e0, loose.e_cs, dense.e_cs, loose.eta_cs, dense.eta_cs);
  EXPECT_GT(loose.e0 - dense.e0, 0.05);  // two different states
  EXPECT_GT(dense.e_cs, dense.e0 + 0.05);  // the dense dilates
  // The "loose" starts near its critical state (e 0.80-0.83 against
  // 0.81-0.83 at the end): with these beads deposition at friction 1.0 is
  // as loose as this box allows, and seeds 3-5 contract on average while
  // seeds 6-8 dilate (mean e 0.809 to 0.821). So what is held is that it
  // changes far less than the dense does, not the sign of its change.
  EXPECT_LT(std::abs(loose.e_cs - loose.e0), 0.5 * (dense.e_cs - dense.e0));
  // One critical state: the void ratios meet, and the stress ratios agree
  // within 10 % (the criterion).
  EXPECT_LT(std::abs(loose.e_cs - dense.e_cs), 0.2 * (loose.e0 - dense.e0));
  EXPECT_LT(std::abs(loose.eta_cs - dense.eta_cs), 0.1 * 0.5 * (loose.eta_cs + dense.eta_cs));
  // The dense specimens peak above their critical state.
  EXPECT_GT(dense.eta_peak, 1.15 * dense.eta_cs);
}
