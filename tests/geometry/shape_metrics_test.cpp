// Shape metrics against closed forms: sphericity of a sphere and a cube,
// Wadell roundness of a sphere, a sharp cube and cubes with rounded corners.
#include "geometry/shape_metrics.h"

#include "geometry/mass_properties.h"
#include "geometry/mesh_check.h"
#include "geometry/primitives.h"
#include "geometry/rounded_hull.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

namespace grainlab {
namespace {

// A cube of half side a whose edges and corners are rounded with radius r.
TriMesh rounded_cube(double a, double r, int faces) {
  const TriMesh core = box_mesh(a - r, a - r, a - r);
  return rounded_hull_mesh(core.vertices, r, faces);
}

TEST(ShapeMetrics, SphereIsRoundAndSpherical) {
  const ShapeMetrics s = shape_metrics(icosphere(1.0, 5));
  EXPECT_NEAR(s.sphericity, 1.0, 0.01);
  EXPECT_NEAR(s.roundness, 1.0, 0.05);
  std::printf("icosphere(5) sphericity %.5f roundness %.4f\n", s.sphericity, s.roundness);
  EXPECT_NEAR(s.equivalent_diameter, 2.0, 0.01);
  EXPECT_NEAR(s.elongation, 1.0, 0.01);
  EXPECT_NEAR(s.flatness, 1.0, 0.01);
  EXPECT_NEAR(s.convexity, 1.0, 1e-9);
}

TEST(ShapeMetrics, CubeSphericityMatchesClosedForm) {
  const ShapeMetrics s = shape_metrics(box_mesh(0.5, 0.5, 0.5));
  // pi^(1/3) (6 V)^(2/3) / A with V = 1, A = 6.
  const double exact = std::cbrt(std::numbers::pi) * std::pow(6.0, 2.0 / 3.0) / 6.0;
  EXPECT_NEAR(exact, 0.806, 0.001);
  EXPECT_NEAR(s.sphericity, exact, 0.02 * exact);
  EXPECT_NEAR(s.volume, 1.0, 1e-12);
  EXPECT_NEAR(s.surface_area, 6.0, 1e-12);
}

TEST(ShapeMetrics, SharpCubeHasLowRoundness) {
  const ShapeMetrics s = shape_metrics(box_mesh(1.0, 1.0, 1.0));
  EXPECT_LT(s.roundness, 0.15);
  std::printf("sharp cube roundness %.4f\n", s.roundness);
  for (double r : s.projection_roundness) EXPECT_LT(r, 0.15);
}

// The projection of a rounded cube on a face plane is a square of half side a
// with corner arcs of radius r, so R = r / a.
class RoundedCube : public ::testing::TestWithParam<double> {};

TEST_P(RoundedCube, FacePlaneRoundnessIsCornerRadiusOverInscribedRadius) {
  const double a = 1.0, ratio = GetParam();
  const TriMesh m = rounded_cube(a, ratio * a, 4000);
  std::vector<Vec2> pts;
  for (const Vec3& v : m.vertices) pts.emplace_back(v.x(), v.y());
  const OutlineRoundness o = outline_roundness(convex_outline(pts));
  if (ratio < 0.9) {
    EXPECT_EQ(o.corners, 4);  // near 1 the straight sides vanish
  }
  EXPECT_NEAR(o.inscribed_radius, a, 2e-3);  // the tessellation is inscribed
  EXPECT_NEAR(o.roundness, ratio, 0.1 * ratio);
  std::printf("rounded cube r/a %.2f: face-plane roundness %.4f\n", ratio, o.roundness);
}

// A cube's inertia is isotropic, so its principal axes are arbitrary; a box
// with half sides 1, 0.9, 0.8 has definite ones. Its principal projections are
// rounded rectangles with inscribed radii 0.9, 0.8 and 0.8.
TEST_P(RoundedCube, ThreeProjectionRoundnessOfRoundedBox) {
  const double r = GetParam() * 0.8;
  const TriMesh core = box_mesh(1.0 - r, 0.9 - r, 0.8 - r);
  const ShapeMetrics s = shape_metrics(rounded_hull_mesh(core.vertices, r, 4000));
  const double expected = r * (1 / 0.9 + 1 / 0.8 + 1 / 0.8) / 3;
  EXPECT_NEAR(s.roundness, expected, 0.1 * expected);
  EXPECT_NEAR(s.projection_roundness[0], r / 0.9, 0.15 * r / 0.9);
  std::printf("rounded box r %.3f: roundness %.4f (expected %.4f)\n", r, s.roundness, expected);
}

INSTANTIATE_TEST_SUITE_P(Ratios, RoundedCube, ::testing::Values(0.2, 0.35, 0.5, 0.7, 0.9));

TEST(ShapeMetrics, ElongatedBoxDimensionsAndAspectRatios) {
  const ShapeMetrics s = shape_metrics(box_mesh(2.0, 1.0, 0.5));
  EXPECT_NEAR(s.long_axis, 4.0, 1e-9);
  EXPECT_NEAR(s.intermediate_axis, 2.0, 1e-9);
  EXPECT_NEAR(s.short_axis, 1.0, 1e-9);
  EXPECT_NEAR(s.elongation, 0.5, 1e-9);
  EXPECT_NEAR(s.flatness, 0.5, 1e-9);
}

TEST(ShapeMetrics, ConvexityOfAnLShapedSolid) {
  // Two unit cubes side by side plus one on top: volume 3, hull volume 3.5.
  TriMesh m;
  m.vertices = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}, {0, 0, 1}, {2, 0, 1}, {2, 1, 1}, {0, 1, 1},
                {1, 0, 1}, {1, 1, 1}, {0, 0, 2}, {1, 0, 2}, {1, 1, 2}, {0, 1, 2}};
  // Faces of the L prism (extruded along y), wound consistently.
  // Profile in the x-z plane: (0,0) (2,0) (2,1) (1,1) (1,2) (0,2); y = 0 uses ids
  // 0 1 5 8 11 10, y = 1 uses 3 2 6 9 12 13.
  m.faces = {
      {0, 5, 1}, {0, 8, 5}, {0, 10, 8}, {8, 10, 11},   // y = 0 (normal -y)
      {3, 2, 6}, {3, 6, 9}, {3, 9, 13}, {9, 12, 13},   // y = 1 (normal +y)
      {0, 1, 2}, {0, 2, 3},                            // bottom z = 0
      {1, 5, 6}, {1, 6, 2},                            // x = 2
      {5, 8, 9}, {5, 9, 6},                            // z = 1 step
      {8, 11, 12}, {8, 12, 9},                         // x = 1
      {11, 10, 13}, {11, 13, 12},                      // top z = 2
      {10, 0, 3}, {10, 3, 13}};                        // x = 0
  const ShapeMetrics s = shape_metrics(repair_mesh(m, "L-shape"));  // fixes the winding
  EXPECT_NEAR(s.volume, 3.0, 1e-12);
  EXPECT_NEAR(s.convexity, 3.0 / 3.5, 1e-9);
  EXPECT_GT(s.roundness, 0.0);
  EXPECT_LE(s.roundness, 1.0);
}

TEST(Outline, InscribedCircleOfSquareAndTriangle) {
  const std::vector<Vec2> square = {{0, 0}, {2, 0}, {2, 2}, {0, 2}};
  Vec2 c;
  EXPECT_NEAR(largest_inscribed_circle(square, &c), 1.0, 1e-6);
  EXPECT_NEAR(c.x(), 1.0, 1e-5);
  // Equilateral triangle of side 1: r = 1 / (2 sqrt 3).
  const std::vector<Vec2> tri = {{0, 0}, {1, 0}, {0.5, std::sqrt(3.0) / 2}};
  EXPECT_NEAR(largest_inscribed_circle(tri), 1.0 / (2 * std::sqrt(3.0)), 1e-6);
}

TEST(Outline, ConvexOutlineDropsInteriorPoints) {
  const std::vector<Vec2> pts = {{0, 0}, {1, 0}, {0.5, 0.2}, {1, 1}, {0, 1}, {0.5, 0.5}};
  const std::vector<Vec2> h = convex_outline(pts);
  EXPECT_EQ(h.size(), 4u);
}

TEST(Outline, SilhouetteOfTwoTrianglesIsTheirSquare) {
  const std::vector<Vec2> pts = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const std::vector<Face> faces = {{0, 1, 2}, {0, 2, 3}};
  const std::vector<Vec2> loop = silhouette_outline(pts, faces, 200);
  double area = 0;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const Vec2& a = loop[i];
    const Vec2& b = loop[(i + 1) % loop.size()];
    area += 0.5 * (a.x() * b.y() - a.y() * b.x());
  }
  EXPECT_NEAR(area, 1.0, 0.02);
  EXPECT_NEAR(largest_inscribed_circle(loop), 0.5, 0.01);
}

TEST(Outline, SilhouetteRoundnessMatchesHullRoundnessOnConvexShapes) {
  const TriMesh m = rounded_cube(1.0, 0.4, 4000);
  std::vector<Vec2> pts;
  for (const Vec3& v : m.vertices) pts.emplace_back(v.x(), v.y());
  const double hull_r = outline_roundness(convex_outline(pts)).roundness;
  const double sil_r = outline_roundness(silhouette_outline(pts, m.faces)).roundness;
  EXPECT_NEAR(hull_r, 0.4, 0.04);
  EXPECT_NEAR(sil_r, hull_r, 0.01);
  std::printf("rounded cube r/a 0.4: hull outline %.4f, silhouette %.4f\n", hull_r, sil_r);
}

// An exact ellipse is the hard case: its corner runs end where the curvature
// radius crosses r_in, where it changes slowly, so small outline errors move
// them. Projected on each principal plane, the silhouette of an ellipsoid (a
// convex solid) reads as its hull outline does.
TEST(Outline, SilhouetteRoundnessMatchesHullRoundnessOnAnEllipsoid) {
  TriMesh m = icosphere(1.0, 4);
  for (Vec3& v : m.vertices) v = v.cwiseProduct(Vec3(1.0, 0.75, 0.6));
  constexpr int kPlanes[3][2] = {{0, 1}, {0, 2}, {1, 2}};
  for (const auto& plane : kPlanes) {
    std::vector<Vec2> pts;
    for (const Vec3& v : m.vertices) pts.emplace_back(v[plane[0]], v[plane[1]]);
    const double hull_r = outline_roundness(convex_outline(pts)).roundness;
    const double sil_r = outline_roundness(silhouette_outline(pts, m.faces)).roundness;
    EXPECT_NEAR(sil_r, hull_r, 0.01) << "plane " << plane[0] << plane[1];
    std::printf("ellipsoid plane %d%d: hull outline %.4f, silhouette %.4f\n", plane[0], plane[1], hull_r, sil_r);
  }
}

double perimeter(const std::vector<Vec2>& loop) {
  double p = 0;
  for (std::size_t i = 0; i < loop.size(); ++i) p += (loop[(i + 1) % loop.size()] - loop[i]).norm();
  return p;
}

// The silhouette is traced below the pixel size: a disc's outline has the
// circle's length and radius, in any orientation. A pixel staircase would be up
// to 4/pi longer (27 % for a circle), which skews the arc-length resampling of
// outline_roundness and made an exact ellipsoid read 0.06 rounder or sharper
// through the silhouette than through its hull outline.
TEST(Outline, SilhouetteOfADiscHasTheCirclesLengthAndRadius) {
  constexpr int kSides = 720;
  std::vector<Vec2> pts = {{0.3, -0.2}};
  std::vector<Face> faces;
  for (int i = 0; i < kSides; ++i) {
    const double t = 2 * std::numbers::pi * i / kSides;
    pts.emplace_back(0.3 + std::cos(t), -0.2 + std::sin(t));
    faces.push_back({0, 1 + i, 1 + (i + 1) % kSides});
  }
  const std::vector<Vec2> loop = silhouette_outline(pts, faces);
  const double exact = 2 * kSides * std::sin(std::numbers::pi / kSides);  // the polygon's perimeter
  EXPECT_NEAR(perimeter(loop), exact, 5e-3 * exact);
  double lo = 2, hi = 0;
  for (const Vec2& p : loop) {
    const double r = (p - Vec2(0.3, -0.2)).norm();
    lo = std::min(lo, r);
    hi = std::max(hi, r);
  }
  const double pixel = 2.0 / 508;  // 512 pixels across, 2 of margin on each side
  EXPECT_GT(lo, 1 - 0.2 * pixel);
  EXPECT_LT(hi, 1 + 0.2 * pixel);
  std::printf("disc silhouette: perimeter %.5f (exact %.5f), radius %.5f to %.5f\n", perimeter(loop), exact, lo, hi);
}

}  // namespace
}  // namespace grainlab
