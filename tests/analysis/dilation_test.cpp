// Dilation angle series (analysis/dilation.h) on analytic d_v(d_h).
#include "analysis/dilation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

using namespace grainlab::analysis;

TEST(DilationAngle, StraightLineGivesItsSlopeEverywhere) {
  // d_v = 0.25 d_h + 1e-4: psi = atan(0.25) at every sample, ends included.
  std::vector<double> dh, dv;
  for (int k = 0; k < 12; ++k) dh.push_back(1e-4 * k), dv.push_back(0.25 * 1e-4 * k + 1e-4);
  const std::vector<double> psi = dilation_angle_series(dh, dv);
  ASSERT_EQ(psi.size(), dh.size());
  for (double p : psi) EXPECT_NEAR(p, std::atan(0.25) * 180 / std::numbers::pi, 1e-9);
}

TEST(DilationAngle, CentralDifferenceOfAParabolaIsExact) {
  // d_v = c d_h^2 with d_h = k h: the central difference over +-2 samples of a
  // parabola is its derivative at the centre, 2 c d_h, exactly (interior samples).
  const double h = 1e-4, c = 50;
  std::vector<double> dh, dv;
  for (int k = 0; k < 10; ++k) dh.push_back(h * k), dv.push_back(c * (h * k) * (h * k));
  const std::vector<double> psi = dilation_angle_series(dh, dv);
  for (int k = 2; k < 8; ++k) EXPECT_NEAR(psi[k], std::atan(2 * c * dh[k]) * 180 / std::numbers::pi, 1e-9) << k;
  // At the first sample the window is [0, 2]: the secant slope c (d_h[2]).
  EXPECT_NEAR(psi[0], std::atan(c * dh[2]) * 180 / std::numbers::pi, 1e-9);
}

TEST(DilationAngle, UndefinedWhereTheBoxDoesNotAdvance) {
  const std::vector<double> dh = {0, 0, 0, 0, 0, 1e-4, 2e-4};
  const std::vector<double> dv = {0, 1e-6, 2e-6, 3e-6, 4e-6, 5e-6, 6e-6};
  const std::vector<double> psi = dilation_angle_series(dh, dv);
  EXPECT_TRUE(std::isnan(psi[0]) && std::isnan(psi[1]) && std::isnan(psi[2]));
  EXPECT_FALSE(std::isnan(psi[3]));  // window [1, 5]: d_h advances
  // Contraction gives negative angles.
  const std::vector<double> down = {0, -1e-5, -2e-5, -3e-5, -4e-5};
  const std::vector<double> ahead = {0, 1e-4, 2e-4, 3e-4, 4e-4};
  for (double p : dilation_angle_series(ahead, down)) EXPECT_NEAR(p, -std::atan(0.1) * 180 / std::numbers::pi, 1e-9);
  EXPECT_THROW(dilation_angle_series(ahead, dv), std::invalid_argument);
}
