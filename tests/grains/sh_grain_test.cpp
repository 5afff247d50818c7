// SH grains: a sphere and an ellipsoid written as coefficient files, read and
// meshed at the default 2000 faces, against their analytic volume and area;
// a rotated grain's coefficients give the rotated body; scaling; and every
// kind of bad file refused with the file and line.
#include "grains/sh_grain.h"

#include "geometry/mass_properties.h"
#include "geometry/mesh_check.h"
#include "geometry/shape_metrics.h"
#include "geometry/test_helpers.h"
#include "grains/sh_test_shapes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>

namespace grainlab {
namespace {

constexpr double kPi = std::numbers::pi;

double area(const TriMesh& m) {
  double a = 0;
  for (const Face& f : m.faces) {
    a += 0.5 * (m.vertices[f[1]] - m.vertices[f[0]]).cross(m.vertices[f[2]] - m.vertices[f[0]]).norm();
  }
  return a;
}

TEST(ShGrain, SphereOfOneCoefficientHasTheSpheresVolumeAndArea) {
  test::TempDir dir;
  ShCoefficients c(0);
  c.at(0, 0) = std::sqrt(4 * kPi) * 1.5;  // r = a_00 Y_00 = 1.5
  write_sh_file(c, dir / "ball.dat");
  const TriMesh m = load_sh_grain(dir / "ball.dat", 2000, ShOptions{1e-3, 0});
  EXPECT_EQ(m.faces.size(), 2000u);
  EXPECT_TRUE(check_mesh(m).ok()) << check_mesh(m).describe();
  const double r = 1.5e-3;
  EXPECT_NEAR(mass_properties(m).volume / (4.0 / 3 * kPi * r * r * r), 1, 0.005);
  EXPECT_NEAR(area(m) / (4 * kPi * r * r), 1, 0.005);
  for (const Vec3& v : m.vertices) EXPECT_NEAR(v.norm(), r, 0.005 * r);  // on the sphere, moved out by the sag
}

TEST(ShGrain, EllipsoidFromQuadratureHasTheEllipsoidsVolumeAndArea) {
  test::TempDir dir;
  const double a = 1.0, b = 0.8, c = 0.6;  // mm
  write_sh_file(test::ellipsoid_coefficients(a, b, c, 30), dir / "ellipsoid.dat");
  const ShCoefficients back = read_sh_file(dir / "ellipsoid.dat");
  EXPECT_EQ(back.degree, 30);
  const TriMesh m = load_sh_grain(dir / "ellipsoid.dat", 2000, ShOptions{1e-3, 0});
  EXPECT_TRUE(check_mesh(m).ok());
  // Exact area (Legendre's form, a >= b >= c): 2 pi c^2 + 2 pi a b / sin(p) (E(p, k) sin^2 p + F(p, k) cos^2 p),
  // cos p = c / a, k^2 = a^2 (b^2 - c^2) / (b^2 (a^2 - c^2)).
  const double p = std::acos(c / a), k = std::sqrt(a * a * (b * b - c * c) / (b * b * (a * a - c * c)));
  const double exact_area = 2 * kPi * c * c + 2 * kPi * a * b / std::sin(p) *
                                                  (std::ellint_2(k, p) * std::pow(std::sin(p), 2) +
                                                   std::ellint_1(k, p) * std::pow(std::cos(p), 2));
  EXPECT_NEAR(mass_properties(m).volume / (4.0 / 3 * kPi * a * b * c * 1e-9), 1, 0.005);
  EXPECT_NEAR(area(m) / (exact_area * 1e-6), 1, 0.005);
  // The principal extents are the axes (the vertices lie on the surface, just inside its extremes).
  const ShapeMetrics s = shape_metrics(m);
  EXPECT_NEAR(s.long_axis, 2 * a * 1e-3, 0.01 * a * 1e-3);
  EXPECT_NEAR(s.short_axis, 2 * c * 1e-3, 0.01 * a * 1e-3);
}

TEST(ShGrain, RotatedCoefficientsGiveTheRotatedBody) {
  const ShCoefficients c = test::lumpy_grain(8);
  const Mat3 rot = Eigen::AngleAxisd(1.1, Vec3(0.3, -1, 0.5).normalized()).toRotationMatrix();
  const SphereQuadrature q = sphere_quadrature(8);
  std::vector<double> r;
  for (const Vec3& u : q.directions) r.push_back(sh_radius(c, rot.transpose() * u));
  const ShCoefficients turned = sh_project(q, r, 8);
  // Pointwise: r'(R u) = r(u).
  for (const Vec3& u : sphere_quadrature(5).directions) {
    EXPECT_NEAR(sh_radius(turned, rot * u), sh_radius(c, u), 1e-12);
  }
  // The bodies: volume, centroid and inertia tensor turn with R.
  const MassProperties a = mass_properties(sh_mesh(c, 2000, "a")), b = mass_properties(sh_mesh(turned, 2000, "b"));
  EXPECT_NEAR(b.volume / a.volume, 1, 0.003);
  EXPECT_LT((b.centroid - rot * a.centroid).norm(), 0.005);
  const Mat3 expected = rot * a.inertia * rot.transpose();
  EXPECT_LT((b.inertia - expected).norm(), 0.01 * a.inertia.norm());
  EXPECT_GT((b.inertia - a.inertia).norm(), 0.05 * a.inertia.norm());  // it did turn
}

TEST(ShGrain, ScalesByAUnitOrToAnEquivalentDiameter) {
  test::TempDir dir;
  write_sh_file(test::ellipsoid_coefficients(2, 1.5, 1, 12), dir / "e.dat");
  const TriMesh mm = load_sh_grain(dir / "e.dat", 500, ShOptions{1e-3, 0});
  const TriMesh um = load_sh_grain(dir / "e.dat", 500, ShOptions{1e-6, 0});
  EXPECT_NEAR(mass_properties(mm).volume / mass_properties(um).volume, 1e9, 1e-3);
  const TriMesh d = load_sh_grain(dir / "e.dat", 500, ShOptions{1e-3, 0.8e-3});
  EXPECT_NEAR(std::cbrt(6 * mass_properties(d).volume / kPi), 0.8e-3, 1e-12);
}

// A valid degree-2 file's lines, VCCTL's layout.
std::vector<std::string> good_lines() {
  ShCoefficients c(2);
  c.at(0, 0) = 10;
  c.at(2, 0) = 0.5;
  c.at(1, 1) = {0.1, 0.2};
  c.at(1, -1) = {-0.1, 0.2};
  test::TempDir dir;
  write_sh_file(c, dir / "g.dat");
  std::ifstream in(dir / "g.dat");
  std::vector<std::string> lines;
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  return lines;
}

std::string refusal(const std::vector<std::string>& lines, bool final_newline = true) {
  test::TempDir dir;
  {
    std::ofstream out(dir / "bad.dat");
    for (std::size_t i = 0; i < lines.size(); ++i) out << lines[i] << (i + 1 < lines.size() || final_newline ? "\n" : "");
  }
  return test::input_error_of([&] { load_sh_grain(dir / "bad.dat", 200, ShOptions{}); });
}

TEST(ShGrain, BadFilesAreRefusedNamingFileAndLine) {
  std::vector<std::string> lines = good_lines();
  ASSERT_EQ(lines.size(), 9u);
  EXPECT_EQ(refusal(lines), "(no InputError)");

  std::vector<std::string> cut = lines;  // truncated in the middle of its last line
  cut.back() = cut.back().substr(0, 14);
  EXPECT_CONTAINS(refusal(cut, false), "bad.dat:9: expected four numbers");
  EXPECT_CONTAINS(refusal(cut, false), "truncated");

  std::vector<std::string> missing(lines.begin(), lines.end() - 2);  // truncated at a line's end
  EXPECT_CONTAINS(refusal(missing), "no line for (n, m) = (2, -1)");
  EXPECT_CONTAINS(refusal(missing), "has 9 lines");

  std::vector<std::string> dropped = lines;  // a degree left out in the middle
  dropped.erase(dropped.begin() + 2);
  EXPECT_CONTAINS(refusal(dropped), "no line for (n, m) = (1, 0)");

  std::vector<std::string> twice = lines;
  twice.push_back(lines[4]);
  EXPECT_CONTAINS(refusal(twice), "bad.dat:10: (n, m) = (2, 2) is given twice, here and on line 5");

  std::vector<std::string> nan = lines;
  nan[5] = "   2   1                 nan        0.0000000000";
  EXPECT_CONTAINS(refusal(nan), "bad.dat:6: a_nm for (n, m) = (2, 1) is not a finite number");

  std::vector<std::string> order = lines;
  order[5] = "   2   3        0.0000000000        0.0000000000";
  EXPECT_CONTAINS(refusal(order), "bad.dat:6: (n, m) = (2, 3) is not a degree and order");

  std::vector<std::string> negative_mean = lines;
  negative_mean[0] = "   0   0       -1.0000000000        0.0000000000";
  EXPECT_CONTAINS(refusal(negative_mean), "a_00 = -1 must be positive");

  std::vector<std::string> negative_radius = lines;  // r = 10 Y_00 + 20 Y_10 < 0 towards -z
  negative_radius[2] = "   1   0       20.0000000000        0.0000000000";
  const std::string e = refusal(negative_radius);
  EXPECT_CONTAINS(e, "bad.dat: the radius is");
  EXPECT_CONTAINS(e, "not positive");
  EXPECT_CONTAINS(e, "theta = 1");  // near the south pole: theta between 100 and 180 deg

  EXPECT_CONTAINS(refusal({}), "holds no coefficient line");
  EXPECT_CONTAINS(test::input_error_of([] { read_sh_file("/nonexistent/x.dat"); }), "cannot open spherical-harmonic file");
}

}  // namespace
}  // namespace grainlab
