// Fabric tensors phi_ij, phi_ijkl, their deviatoric parts, principal values and
// the octahedral fabric factor Psi on sets of normals whose answers are known.
#include "analysis/fabric.h"
#include "core/rng.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace grainlab;
using namespace grainlab::analysis;

namespace {

double max_abs(const Mat3& m) { return m.cwiseAbs().maxCoeff(); }

// Normals along +-x, +-y, +-z with weights wx, wy, wz (each sign once).
void axis_set(double wx, double wy, double wz, std::vector<Vec3>& n, std::vector<double>& w) {
  n.clear();
  w.clear();
  const double ws[3] = {wx, wy, wz};
  for (int a = 0; a < 3; ++a)
    for (double sign : {1.0, -1.0}) {
      n.push_back(sign * Vec3::Unit(a));
      w.push_back(ws[a]);
    }
}

}  // namespace

TEST(Fabric, UniformRandomNormalsAreIsotropic) {
  Rng rng(2024);
  std::vector<Vec3> n(100000);
  for (Vec3& v : n) v = rng.unit_vector();
  const FabricTensors f = fabric_tensors(n);
  const double psi = octahedral_fabric_factor(f.phi);
  const double phi_err = max_abs(f.phi - Mat3::Identity() / 3.0);
  // Isotropic fourth moment: (1/15)(d_ij d_kl + d_ik d_jl + d_il d_jk) = S(dd)/5.
  const double phi4_err = f.phi4.max_abs_diff((1.0 / 5.0) * sym_delta_delta());
  std::printf("  100000 uniform normals: Psi = %.5f, max |phi - I/3| = %.5f, max |phi4 - iso| = %.5f\n", psi,
              phi_err, phi4_err);
  EXPECT_EQ(f.count, 100000u);
  EXPECT_LT(psi, 0.01);
  EXPECT_LT(phi_err, 0.01);
  EXPECT_LT(phi4_err, 0.01);
  EXPECT_NEAR(f.phi.trace(), 1.0, 1e-12);
}

TEST(Fabric, NormalsAllAlongOneAxisGiveTheLargestPsi) {
  // Mixed signs: a normal has no sign, the even-order tensors do not see it.
  const std::vector<Vec3> n = {Vec3::UnitZ(), -Vec3::UnitZ(), 3.0 * Vec3::UnitZ()};  // lengths ignored
  const FabricTensors f = fabric_tensors(n);
  Mat3 expect = Mat3::Zero();
  expect(2, 2) = 1;
  EXPECT_LT(max_abs(f.phi - expect), 1e-14);
  Tensor4 expect4;
  expect4(2, 2, 2, 2) = 1;
  EXPECT_LT(f.phi4.max_abs_diff(expect4), 1e-14);
  EXPECT_NEAR(octahedral_fabric_factor(f.phi), 1.0, 1e-12);
  const Principal p = principal(f.phi);
  EXPECT_NEAR(p.values[0], 1.0, 1e-12);
  EXPECT_NEAR(p.values[1], 0.0, 1e-12);
  EXPECT_NEAR(p.values[2], 0.0, 1e-12);
  EXPECT_NEAR(std::abs(p.directions.col(0).z()), 1.0, 1e-12);
  EXPECT_NEAR(octahedral_fabric_factor(p.values), 1.0, 1e-12);
}

TEST(Fabric, WeightedAxisNormalsGiveTheirKnownTensors) {
  std::vector<Vec3> n;
  std::vector<double> w;
  axis_set(1, 2, 3, n, w);
  const FabricTensors f = fabric_tensors(n, w);
  EXPECT_DOUBLE_EQ(f.total_weight, 12.0);
  EXPECT_LT(max_abs(f.phi - Vec3(1, 2, 3).asDiagonal().toDenseMatrix() / 6.0), 1e-14);
  // phi_ijkl is non-zero only at iiii, where it equals phi_ii.
  Tensor4 expect4;
  for (int a = 0; a < 3; ++a) expect4(a, a, a, a) = (a + 1) / 6.0;
  EXPECT_LT(f.phi4.max_abs_diff(expect4), 1e-14);
  // Principal values 1/2, 1/3, 1/6 along z, y, x.
  const Principal p = principal(f.phi);
  EXPECT_NEAR(p.values[0], 0.5, 1e-14);
  EXPECT_NEAR(p.values[1], 1.0 / 3.0, 1e-14);
  EXPECT_NEAR(p.values[2], 1.0 / 6.0, 1e-14);
  EXPECT_NEAR(std::abs(p.directions(2, 0)), 1.0, 1e-12);
  EXPECT_NEAR(std::abs(p.directions(1, 1)), 1.0, 1e-12);
  EXPECT_NEAR(std::abs(p.directions(0, 2)), 1.0, 1e-12);
  // Eq. 29: (1/sqrt2) sqrt((1/6)^2 + (1/3)^2 + (1/6)^2) = 1/sqrt(12).
  const double psi = 1.0 / std::sqrt(12.0);
  EXPECT_NEAR(octahedral_fabric_factor(p.values), psi, 1e-14);
  EXPECT_NEAR(octahedral_fabric_factor(f.phi), psi, 1e-14);
}

TEST(Fabric, CubicSetIsIsotropicInPhiButNotInPhi4) {
  // Equal weights on the six axis directions: phi = I/3 (Psi = 0), but the
  // fourth-order deviator is not zero: D4_xxxx = 1/3 - (6/7)(1/3) + 3/35 = 2/15.
  std::vector<Vec3> n;
  std::vector<double> w;
  axis_set(1, 1, 1, n, w);
  const FabricTensors f = fabric_tensors(n, w);
  EXPECT_LT(octahedral_fabric_factor(f.phi), 1e-14);
  const Tensor4 d4 = deviatoric_part(f.phi4);
  EXPECT_NEAR(d4(0, 0, 0, 0), 2.0 / 15.0, 1e-14);
  EXPECT_NEAR(d4(2, 2, 2, 2), 2.0 / 15.0, 1e-14);
  // D4_xxyy = 0 - (6/7)(1/6)(1/3 + 1/3) + (3/35)(1/3) = -1/15.
  EXPECT_NEAR(d4(0, 0, 1, 1), -1.0 / 15.0, 1e-14);
  EXPECT_NEAR(d4(0, 1, 0, 1), -1.0 / 15.0, 1e-14);
}

TEST(Fabric, DeviatoricPartsAreTracelessOverEveryIndexPair) {
  Rng rng(7);
  const Mat3 stretch = Vec3(1.0, 0.5, 2.0).asDiagonal();
  const Quat r = rng.rotation();
  std::vector<Vec3> n(2000);
  for (Vec3& v : n) v = r * (stretch * Vec3(rng.normal(), rng.normal(), rng.normal()));
  const FabricTensors f = fabric_tensors(n);
  const Mat3 d2 = deviatoric_part(f.phi);
  EXPECT_NEAR(d2.trace(), 0.0, 1e-14);
  EXPECT_GT(d2.norm(), 0.1);  // the set is anisotropic
  const Tensor4 d4 = deviatoric_part(f.phi4);
  double worst = 0, size = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      double t_ij_kk = 0, t_ik_jk = 0, t_kk_ij = 0;  // traces over (3,4), (2,4), (1,2)
      for (int k = 0; k < 3; ++k) {
        t_ij_kk += d4(i, j, k, k);
        t_ik_jk += d4(i, k, j, k);
        t_kk_ij += d4(k, k, i, j);
      }
      worst = std::max({worst, std::abs(t_ij_kk), std::abs(t_ik_jk), std::abs(t_kk_ij)});
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l) size = std::max(size, std::abs(d4(i, j, k, l)));
    }
  EXPECT_LT(worst, 1e-14);
  EXPECT_GT(size, 0.01);
}

TEST(Fabric, SignsRotationsAndPrincipalFrame) {
  Rng rng(3);
  std::vector<Vec3> n(500), flipped(500);
  for (std::size_t m = 0; m < n.size(); ++m) {
    n[m] = Vec3(rng.normal(), 0.3 * rng.normal(), 2.0 * rng.normal()).normalized();
    flipped[m] = (m % 3 == 0) ? -n[m] : n[m];
  }
  const FabricTensors a = fabric_tensors(n), b = fabric_tensors(flipped);
  EXPECT_LT(max_abs(a.phi - b.phi), 1e-14);
  EXPECT_LT(a.phi4.max_abs_diff(b.phi4), 1e-14);
  // Psi is invariant under a rotation of the normals, and the principal
  // frame diagonalises phi.
  const Quat r = rng.rotation();
  std::vector<Vec3> turned(n.size());
  for (std::size_t m = 0; m < n.size(); ++m) turned[m] = r * n[m];
  const FabricTensors c = fabric_tensors(turned);
  const double psi = octahedral_fabric_factor(a.phi);
  EXPECT_NEAR(octahedral_fabric_factor(c.phi), psi, 1e-14);
  const Principal p = principal(c.phi);
  EXPECT_NEAR(octahedral_fabric_factor(p.values), psi, 1e-14);
  EXPECT_GE(p.values[0], p.values[1]);
  EXPECT_GE(p.values[1], p.values[2]);
  EXPECT_NEAR(p.directions.determinant(), 1.0, 1e-12);
  const Mat3 diag = p.directions.transpose() * c.phi * p.directions;
  EXPECT_LT(max_abs(diag - p.values.asDiagonal().toDenseMatrix()), 1e-14);
}

TEST(Fabric, BadInputIsRefused) {
  const std::vector<Vec3> n = {Vec3::UnitX(), Vec3::Zero()};
  EXPECT_THROW(fabric_tensors(n), std::invalid_argument);
  const std::vector<Vec3> one = {Vec3::UnitX()};
  const std::vector<double> two = {1, 2};
  EXPECT_THROW(fabric_tensors(one, two), std::invalid_argument);
  EXPECT_EQ(fabric_tensors({}).count, 0u);
}

TEST(Fabric, ContactNormalsOfASubsetCountOncePerSubsetGrain) {
  State s;
  s.bodies.resize(4);
  const auto pair = [](Index a, Index b, bool touching, Vec3 n) {
    Contact pc;
    pc.a = a;
    pc.b = b;
    pc.geo.touching = touching;
    pc.geo.normal = n;
    return pc;
  };
  s.contacts = {pair(0, 1, true, Vec3::UnitX()), pair(1, 2, true, Vec3::UnitY()), pair(2, 3, false, Vec3::UnitZ())};
  EXPECT_EQ(contact_normals(s).size(), 2u);
  const GrainMask m = {0, 1, 1, 0};  // grains 1, 2: contact 0-1 once, 1-2 twice
  const std::vector<Vec3> n = contact_normals(s, &m);
  ASSERT_EQ(n.size(), 3u);
  const FabricTensors f = fabric_tensors(n);
  EXPECT_NEAR(f.phi(0, 0), 1.0 / 3.0, 1e-14);
  EXPECT_NEAR(f.phi(1, 1), 2.0 / 3.0, 1e-14);
  const GrainMask wrong = {1, 1};
  EXPECT_THROW(contact_normals(s, &wrong), std::invalid_argument);
}
