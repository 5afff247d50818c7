// Kanatani's density: integrates to one over the sphere and reproduces the
// second- and fourth-order fabric tensors it was built from (the coefficients
// 1/(4pi), 15/2 and 315/8 derived in kanatani.h; the paper's 1/(2pi) and 2/15
// fail all three).
#include "analysis/kanatani.h"
#include "core/rng.h"
#include "sphere_quadrature.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

using namespace grainlab;
using namespace grainlab::analysis;
using testing_support::sphere_quadrature;

namespace {

// An anisotropic, non-axisymmetric sample: stretched Gaussian directions in a
// tilted frame, so every component of phi_ij and phi_ijkl is non-zero.
FabricTensors anisotropic_fabric() {
  Rng rng(99);
  const Mat3 stretch = Vec3(1.0, 0.5, 2.0).asDiagonal();
  const Quat tilt = rng.rotation();
  std::vector<Vec3> n(20000);
  for (Vec3& v : n) v = tilt * (stretch * Vec3(rng.normal(), rng.normal(), rng.normal()));
  return fabric_tensors(n);
}

struct Moments {
  double m0 = 0;
  Mat3 m2 = Mat3::Zero();
  Tensor4 m4;
};

// int f, int n_i n_j f, int n_i n_j n_k n_l f over the sphere. The integrands
// are polynomials of degree <= 8 in n: 24 x 48 points integrate them to rounding.
Moments moments(const KanataniDensity& f) {
  Moments m;
  for (const auto& p : sphere_quadrature(24, 48)) {
    const double w = p.weight * f(p.n);
    m.m0 += w;
    m.m2 += w * p.n * p.n.transpose();
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        for (int k = 0; k < 3; ++k)
          for (int l = 0; l < 3; ++l) m.m4(i, j, k, l) += w * p.n[i] * p.n[j] * p.n[k] * p.n[l];
  }
  return m;
}

}  // namespace

TEST(Kanatani, QuadratureIsExactForLowDegreePolynomials) {
  // The test's own tool: area 4 pi, int n_z^4 = 4 pi / 5, int n_x^2 n_y^2 = 4 pi / 15.
  double area = 0, z4 = 0, x2y2 = 0;
  for (const auto& p : sphere_quadrature(24, 48)) {
    area += p.weight;
    z4 += p.weight * std::pow(p.n.z(), 4);
    x2y2 += p.weight * p.n.x() * p.n.x() * p.n.y() * p.n.y();
  }
  EXPECT_NEAR(area, 4 * std::numbers::pi, 1e-12);
  EXPECT_NEAR(z4, 4 * std::numbers::pi / 5, 1e-12);
  EXPECT_NEAR(x2y2, 4 * std::numbers::pi / 15, 1e-12);
}

TEST(Kanatani, IntegratesToOneAndReproducesTheFabricTensors) {
  const FabricTensors fab = anisotropic_fabric();
  const double psi = octahedral_fabric_factor(fab.phi);
  ASSERT_GT(psi, 0.2);  // strongly anisotropic
  const KanataniDensity f = kanatani_density(fab);
  const Moments m = moments(f);
  const double e0 = std::abs(m.m0 - 1.0);
  const double e2 = (m.m2 - fab.phi).cwiseAbs().maxCoeff();
  const double e4 = m.m4.max_abs_diff(fab.phi4);
  std::printf("  anisotropic sample (Psi = %.3f): |int f - 1| = %.2e, max |int nn f - phi| = %.2e, "
              "max |int nnnn f - phi4| = %.2e\n", psi, e0, e2, e4);
  EXPECT_LT(e0, 1e-6);
  EXPECT_LT(e2, 1e-6);
  EXPECT_LT(e4, 1e-6);
  // Even: f(n) = f(-n).
  const Vec3 n = Vec3(0.3, -0.4, 0.866).normalized();
  EXPECT_NEAR(f(n), f(-n), 1e-15);
}

TEST(Kanatani, SecondOrderApproximationKeepsOnlyTheFirstTwoMoments) {
  const FabricTensors fab = anisotropic_fabric();
  const Moments m = moments(kanatani_density(fab, false));
  EXPECT_LT(std::abs(m.m0 - 1.0), 1e-6);
  EXPECT_LT((m.m2 - fab.phi).cwiseAbs().maxCoeff(), 1e-6);
  // The sample has a fourth-order deviator that the truncation drops.
  EXPECT_GT(m.m4.max_abs_diff(fab.phi4), 1e-3);
}

TEST(Kanatani, IsotropicFabricGivesTheUniformDensity) {
  FabricTensors iso;
  iso.phi = Mat3::Identity() / 3.0;
  iso.phi4 = (1.0 / 5.0) * sym_delta_delta();
  const KanataniDensity f = kanatani_density(iso);
  for (const Vec3& n : std::vector<Vec3>{Vec3::UnitX(), Vec3(1, 1, 1).normalized(), Vec3(0.2, -0.9, 0.1).normalized()})
    EXPECT_NEAR(f(n), 1.0 / (4 * std::numbers::pi), 1e-15);
}

TEST(Kanatani, CubicSetHasItsKnownFourthOrderCoefficient) {
  // Six normals +-x, +-y, +-z: D_ij = 0, D_xxxx = (315/8)(2/15) = 21/4 and
  // D_xxyy = (315/8)(-1/15) = -21/8 (fabric_test.cpp has the deviators), the
  // other components 0 or these by symmetry. Along an axis D4 n^4 = 21/4; along
  // the cube diagonal n = (1,1,1)/sqrt3 it is (1/9)[3 D_xxxx + 3 axis pairs x
  // 6 orderings x D_xxyy] = (1/9)(63/4 - 189/4) = -7/2: the truncated series
  // goes negative there, as a six-spike distribution must.
  std::vector<Vec3> n;
  for (int a = 0; a < 3; ++a) {
    n.push_back(Vec3::Unit(a));
    n.push_back(-Vec3::Unit(a));
  }
  const KanataniDensity f = kanatani_density(fabric_tensors(n));
  EXPECT_LT(f.D2.cwiseAbs().maxCoeff(), 1e-14);
  EXPECT_NEAR(f.D4(0, 0, 0, 0), 21.0 / 4.0, 1e-13);
  EXPECT_NEAR(f(Vec3::UnitX()), (1 + 21.0 / 4.0) / (4 * std::numbers::pi), 1e-14);
  EXPECT_NEAR(f(Vec3(1, 1, 1).normalized()), (1 - 7.0 / 2.0) / (4 * std::numbers::pi), 1e-14);
}
