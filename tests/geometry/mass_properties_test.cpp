// Mass properties against closed forms: boxes, tetrahedra, spheres, ellipsoids.
#include "geometry/mass_properties.h"

#include "geometry/primitives.h"
#include "test_helpers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <utility>

namespace grainlab {
namespace {

// Largest entry of |a - b| relative to the largest entry of |b|.
double rel_err(const Mat3& a, const Mat3& b) { return (a - b).cwiseAbs().maxCoeff() / b.cwiseAbs().maxCoeff(); }
double rel_err(const Vec3& a, const Vec3& b) { return (a - b).norm() / b.norm(); }

// Applies x -> R x + t to every vertex.
TriMesh transformed(TriMesh m, const Mat3& R, const Vec3& t) {
  for (Vec3& v : m.vertices) v = R * v + t;
  return m;
}

// Closed-form inertia of a solid box with half extents h about its centre, per unit density.
Mat3 box_inertia(const Vec3& h) {
  const double v = 8 * h.x() * h.y() * h.z();
  const Vec3 q = h.cwiseAbs2();
  return Vec3(v * (q.y() + q.z()) / 3, v * (q.x() + q.z()) / 3, v * (q.x() + q.y()) / 3).asDiagonal();
}

TEST(MassProperties, AxisAlignedBox) {
  const Vec3 h(0.3, 0.5, 0.7);
  const MassProperties mp = mass_properties(box_mesh(h.x(), h.y(), h.z()));
  EXPECT_NEAR(mp.volume / (8 * h.prod()) - 1, 0, 1e-12);
  EXPECT_LT(mp.centroid.norm(), 1e-15);
  EXPECT_LT(rel_err(mp.inertia, box_inertia(h)), 1e-12);
}

TEST(MassProperties, RotatedTranslatedBoxHasRotatedInertia) {
  const Vec3 h(0.2, 0.5, 0.9);
  const Mat3 R = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  const Vec3 t(120.0, -45.0, 33.0);  // far from the origin: tests the shifted origin
  const MassProperties mp = mass_properties(transformed(box_mesh(h.x(), h.y(), h.z()), R, t));
  EXPECT_LT(std::abs(mp.volume / (8 * h.prod()) - 1), 1e-9);
  EXPECT_LT(rel_err(mp.centroid, t), 1e-9);
  const Mat3 expected = R * box_inertia(h) * R.transpose();
  EXPECT_GT(std::abs(expected(0, 1)), 1e-3);  // products of inertia are really tested
  EXPECT_LT(rel_err(mp.inertia, expected), 1e-9);
}

TEST(MassProperties, PrincipalAxesRecoverTheRotation) {
  const Vec3 h(0.2, 0.5, 0.9);
  const Mat3 R = Eigen::AngleAxisd(-1.1, Vec3(0.3, -1, 0.4).normalized()).toRotationMatrix();
  const MassProperties mp = mass_properties(transformed(box_mesh(h.x(), h.y(), h.z()), R, Vec3(1, 2, 3)));
  // Ascending: the longest side (z) has the smallest moment, then y, then x.
  const Mat3 I0 = box_inertia(h);
  const Vec3 expected(I0(2, 2), I0(1, 1), I0(0, 0));
  EXPECT_LT(rel_err(mp.principal_moments, expected), 1e-9);
  EXPECT_LT(mp.principal_moments[0], mp.principal_moments[1]);
  EXPECT_LT(mp.principal_moments[1], mp.principal_moments[2]);
  const Mat3& A = mp.principal_axes;
  EXPECT_NEAR(A.determinant(), 1.0, 1e-12);
  EXPECT_NEAR(std::abs(A.col(0).dot(R.col(2))), 1.0, 1e-9);
  EXPECT_NEAR(std::abs(A.col(1).dot(R.col(1))), 1.0, 1e-9);
  EXPECT_NEAR(std::abs(A.col(2).dot(R.col(0))), 1.0, 1e-9);
  EXPECT_LT(rel_err(A * mp.principal_moments.asDiagonal() * A.transpose(), mp.inertia), 1e-12);
}

TEST(MassProperties, UnitRightTetrahedronByHand) {
  // V = 1/6, centroid 1/4; int x^2 = 1/60, int xy = 1/120 about the corner, so
  // about the centroid int x^2 = 1/60 - 1/96 = 1/160, int xy = 1/120 - 1/96 = -1/480:
  // I_xx = 2/160 = 1/80, I_xy = +1/480.
  const MassProperties mp = mass_properties(tetrahedron_mesh({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}));
  EXPECT_NEAR(mp.volume * 6, 1.0, 1e-14);
  EXPECT_LT(rel_err(mp.centroid, Vec3::Constant(0.25)), 1e-14);
  Mat3 expected;
  expected << 1.0 / 80, 1.0 / 480, 1.0 / 480,  //
      1.0 / 480, 1.0 / 80, 1.0 / 480,          //
      1.0 / 480, 1.0 / 480, 1.0 / 80;
  EXPECT_LT(rel_err(mp.inertia, expected), 1e-12);
}

// Tonon (2004), J. Math. Stat. 1(1), Eqs. 2-3: inertia of a tetrahedron about its
// centroid from the vertex coordinates taken relative to the centroid.
Mat3 tonon_inertia(std::array<Vec3, 4> p) {
  const Vec3 g = (p[0] + p[1] + p[2] + p[3]) / 4;
  for (Vec3& v : p) v -= g;
  const double detJ = std::abs((p[1] - p[0]).dot((p[2] - p[0]).cross(p[3] - p[0])));
  // sum_{i<=j} u_i u_j over the four vertices
  auto sq = [&](int k) {
    double s = 0;
    for (int i = 0; i < 4; ++i)
      for (int j = i; j < 4; ++j) s += p[i][k] * p[j][k];
    return s;
  };
  // sum_i 2 u_i w_i + sum_{i != j} u_i w_j
  auto mixed = [&](int k, int l) {
    double s = 0;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) s += (i == j ? 2.0 : 1.0) * p[i][k] * p[j][l];
    return s;
  };
  const double a = detJ * (sq(1) + sq(2)) / 60, b = detJ * (sq(0) + sq(2)) / 60,
               c = detJ * (sq(0) + sq(1)) / 60;
  const double a1 = detJ * mixed(1, 2) / 120, b1 = detJ * mixed(0, 2) / 120,
               c1 = detJ * mixed(0, 1) / 120;
  Mat3 I;
  I << a, -c1, -b1,  //
      -c1, b, -a1,   //
      -b1, -a1, c;
  return I;
}

TEST(MassProperties, ArbitraryTetrahedronMatchesTonon) {
  // Tonon's worked example, with his published values (mu = 1).
  const std::array<Vec3, 4> p{Vec3(8.33220, -11.86875, 0.93355), Vec3(0.75523, 5.00000, 16.37072),
                              Vec3(52.61236, 5.00000, -5.38580), Vec3(2.00000, 5.00000, 3.00000)};
  const MassProperties mp = mass_properties(tetrahedron_mesh(p[0], p[1], p[2], p[3]));
  const Mat3 closed = tonon_inertia(p);
  EXPECT_LT(rel_err(mp.inertia, closed), 1e-9);
  EXPECT_LT(rel_err(mp.centroid, (p[0] + p[1] + p[2] + p[3]) / 4), 1e-12);
  const double volume = std::abs((p[1] - p[0]).dot((p[2] - p[0]).cross(p[3] - p[0]))) / 6;
  EXPECT_LT(std::abs(mp.volume / volume - 1), 1e-12);
  // Published: a = 43520.33257, b = 194711.28938, c = 191168.76173,
  // a' = 4417.66150, b' = -46343.16662, c' = 11996.20119 (a', b', c' are the
  // yz, xz, xy products). The published vertices are rounded to 5 decimals, so
  // these agree to about 2e-8 only; the check above is the exact one.
  Mat3 published;
  published << 43520.33257, -11996.20119, 46343.16662,  //
      -11996.20119, 194711.28938, -4417.66150,          //
      46343.16662, -4417.66150, 191168.76173;
  EXPECT_LT(rel_err(mp.inertia, published), 1e-7);
}

TEST(MassProperties, SphereConvergesMonotonically) {
  const double r = 0.7, v = 4.0 / 3.0 * std::numbers::pi * r * r * r, i = 0.4 * v * r * r;
  double last_v = INFINITY, last_i = INFINITY;
  for (int s = 1; s <= 6; ++s) {
    const MassProperties mp = mass_properties(icosphere(r, s));
    const double ev = std::abs(mp.volume / v - 1);
    const double ei = rel_err(mp.inertia, Mat3(i * Mat3::Identity()));
    EXPECT_LT(ev, last_v) << "subdivision " << s;
    EXPECT_LT(ei, last_i) << "subdivision " << s;
    last_v = ev;
    last_i = ei;
    EXPECT_LT(mp.centroid.norm(), 1e-12 * r);
  }
  EXPECT_LT(last_v, 1e-3);
  EXPECT_LT(last_i, 1e-3);
}

TEST(MassProperties, EllipsoidConvergesMonotonically) {
  const double a = 1.0, b = 0.7, c = 0.4, v = 4.0 / 3.0 * std::numbers::pi * a * b * c;
  const Mat3 I = Vec3(v * (b * b + c * c) / 5, v * (a * a + c * c) / 5, v * (a * a + b * b) / 5).asDiagonal();
  double last_v = INFINITY, last_i = INFINITY;
  for (int s = 1; s <= 6; ++s) {
    const MassProperties mp = mass_properties(ellipsoid_mesh(a, b, c, s));
    const double ev = std::abs(mp.volume / v - 1);
    const double ei = rel_err(mp.inertia, I);
    EXPECT_LT(ev, last_v) << "subdivision " << s;
    EXPECT_LT(ei, last_i) << "subdivision " << s;
    last_v = ev;
    last_i = ei;
  }
  EXPECT_LT(last_v, 1e-3);
  EXPECT_LT(last_i, 1e-3);
}

TEST(MassProperties, InsideOutMeshRefused) {
  TriMesh m = box_mesh(1, 1, 1);
  for (Face& f : m.faces) std::swap(f[1], f[2]);
  EXPECT_CONTAINS(test::input_error_of([&] { mass_properties(m); }), "inside out");
  EXPECT_CONTAINS(test::input_error_of([] { mass_properties(TriMesh{}); }), "empty");
}

}  // namespace
}  // namespace grainlab
