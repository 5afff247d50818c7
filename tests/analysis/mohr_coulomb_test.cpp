// The Mohr-Coulomb fit (analysis/mohr_coulomb.h) on circles built tangent to a
// known envelope tau = c' + sigma' tan phi'.
#include "analysis/mohr_coulomb.h"

#include "core/error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

using namespace grainlab;
using namespace grainlab::analysis;

namespace {
constexpr double kDeg = std::numbers::pi / 180;

// The circle through sigma_3 tangent to tau = c + sigma tan phi: t = c cos phi + s sin phi with
// s = sigma_3 + t, so t = (c cos phi + sigma_3 sin phi) / (1 - sin phi).
MohrCircle tangent_circle(double sigma3, double phi_deg, double c) {
  const double sp = std::sin(phi_deg * kDeg), t = (c * std::cos(phi_deg * kDeg) + sigma3 * sp) / (1 - sp);
  return mohr_circle(sigma3 + 2 * t, sigma3);
}

std::string refusal(const std::vector<MohrCircle>& circles) {
  try {
    fit_mohr_coulomb(circles);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(MohrCoulomb, Sigma1FromTheStressRatio) {
  // eta = q/p' with p' = (s1 + 2 s3)/3, q = s1 - s3: back from sigma_1 = s3 (3 + 2 eta)/(3 - eta).
  for (double eta : {0.0, 0.5, 1.2, 2.5}) {
    const double s3 = 100e3, s1 = triaxial_sigma1(s3, eta);
    EXPECT_NEAR((s1 - s3) / ((s1 + 2 * s3) / 3), eta, 1e-12) << eta;
  }
  EXPECT_THROW(triaxial_sigma1(100e3, 3.0), InputError);
  EXPECT_THROW(triaxial_sigma1(0.0, 1.0), InputError);
}

TEST(MohrCoulomb, CirclesTangentToAKnownLineRecoverItsCohesionAndAngle) {
  std::vector<MohrCircle> circles;
  for (double s3 : {50e3, 100e3, 200e3}) circles.push_back(tangent_circle(s3, 34.0, 5e3));
  const MohrCoulombFit f = fit_mohr_coulomb(circles);
  EXPECT_NEAR(f.phi_deg, 34.0, 1e-9);
  EXPECT_NEAR(f.c, 5e3, 1e-6);
  EXPECT_NEAR(f.sin_phi, std::sin(34 * kDeg), 1e-12);
  EXPECT_NEAR(f.a, 5e3 * std::cos(34 * kDeg), 1e-6);
  EXPECT_NEAR(f.r_squared, 1.0, 1e-12);
  EXPECT_NEAR(f.rms_residual, 0.0, 1e-6);
  EXPECT_EQ(f.circles, 3);
  // Without cohesion the line goes through the origin; two circles give the exact line.
  const MohrCircle two[] = {tangent_circle(80e3, 31.0, 0), tangent_circle(300e3, 31.0, 0)};
  EXPECT_NEAR(fit_mohr_coulomb(two).phi_deg, 31.0, 1e-9);
  EXPECT_NEAR(fit_mohr_coulomb(two).c, 0.0, 1e-6);
}

TEST(MohrCoulomb, ScatteredCirclesGiveTheLeastSquaresLine) {
  // (s, t) = (100, 40), (200, 100), (300, 130) kPa, by hand: b = 9e9 / 2e10 = 0.45, a = 90 - 0.45 x 200 = 0;
  // residuals -5, 10, -5 kPa: SS_res = 1.5e8 Pa^2 against SS_tot = 4.2e9 Pa^2.
  const std::vector<MohrCircle> c = {{100e3, 40e3}, {200e3, 100e3}, {300e3, 130e3}};
  const MohrCoulombFit f = fit_mohr_coulomb(c);
  EXPECT_NEAR(f.sin_phi, 0.45, 1e-12);
  EXPECT_NEAR(f.a, 0.0, 1e-6);
  EXPECT_NEAR(f.rms_residual, std::sqrt(1.5e8 / 3), 1e-6);
  EXPECT_NEAR(f.r_squared, 1 - 1.5e8 / 4.2e9, 1e-12);
}

TEST(MohrCoulomb, TooFewOrUnusableCirclesAreAClearError) {
  EXPECT_EQ(refusal({}), "0 runs with the stresses needed: a fit needs two or more");
  EXPECT_EQ(refusal({tangent_circle(100e3, 30, 0)}), "1 run with the stresses needed: a fit needs two or more");
  const MohrCircle same = tangent_circle(100e3, 30, 0);
  EXPECT_EQ(refusal({same, same}), "every circle has the same centre: give runs at different sigma_3");
  EXPECT_NE(refusal({{100e3, 90e3}, {200e3, 50e3}}).find("outside (0, 1)"), std::string::npos);
}
