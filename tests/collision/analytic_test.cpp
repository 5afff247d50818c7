// Closed-form narrowphase: sphere-sphere, plane-sphere, plane-polytope.
#include "collision/narrowphase.h"
#include "collision/soft_depth.h"
#include "collision/test_shapes.h"

#include <gtest/gtest.h>

#include <cmath>

namespace grainlab {
namespace {

TEST(Analytic, SphereSphere) {
  Rng rng(41);
  for (int t = 0; t < 2000; ++t) {
    SphereShape a{rng.unit_vector() * 1e-2, rng.uniform(0.5, 1.5) * 1e-3};
    SphereShape b{a.pos + rng.uniform(0.1, 3) * 1e-3 * rng.unit_vector(), rng.uniform(0.5, 1.5) * 1e-3};
    const ContactResult r = collide(a, b);
    const double dist = (b.pos - a.pos).norm();
    EXPECT_NEAR(r.depth, a.radius + b.radius - dist, 1e-15);
    EXPECT_EQ(r.touching, r.depth > 0);
    EXPECT_NEAR(r.normal.norm(), 1, 1e-14);
    EXPECT_NEAR(r.normal.dot(b.pos - a.pos), dist, 1e-15);
    // Midway between the surface points.
    const Vec3 sa = a.pos + a.radius * r.normal, sb = b.pos - b.radius * r.normal;
    EXPECT_LT((r.point - 0.5 * (sa + sb)).norm(), 1e-15);
    // Moving B by depth*normal makes them touch.
    SphereShape moved{b.pos + r.depth * r.normal, b.radius};
    EXPECT_NEAR(collide(a, moved).depth, 0, 1e-15);
  }
  const ContactResult same = collide(SphereShape{Vec3::Zero(), 1}, SphereShape{Vec3::Zero(), 2});
  EXPECT_DOUBLE_EQ(same.depth, 3);
  EXPECT_TRUE(same.normal.allFinite());
}

TEST(Analytic, PlaneSphere) {
  Rng rng(42);
  for (int t = 0; t < 2000; ++t) {
    PlaneShape p{rng.unit_vector(), rng.unit_vector()};
    const double h = rng.uniform(-0.5, 2), rad = rng.uniform(0.5, 1.5);
    const Vec3 tangent = p.normal.cross(rng.unit_vector());
    SphereShape s{p.point + h * p.normal + tangent, rad};
    const ContactResult r = collide(p, s);
    EXPECT_NEAR(r.depth, rad - h, 1e-13);
    EXPECT_EQ(r.normal, p.normal);
    EXPECT_NEAR((r.point - p.point).dot(p.normal), 0.5 * (h - rad), 1e-13);
    EXPECT_LT((r.point - (p.point + tangent)).cross(p.normal).norm(), 1e-13);
  }
}

TEST(Analytic, BoxFlatOnPlanePushesAtFaceCentre) {
  const auto box = testing::box_hull(Vec3(1, 2, 0.5));
  Rng rng(43);
  for (int t = 0; t < 200; ++t) {
    const double depth = rng.uniform(1e-6, 0.1);
    const double yaw = rng.uniform(0, 6.28);
    const Vec3 c(rng.uniform(-5, 5), rng.uniform(-5, 5), 0.5 - depth);
    PolytopeShape s{&box.poly, Eigen::AngleAxisd(yaw, Vec3::UnitZ()).toRotationMatrix(), c, 1,
                    static_cast<Index>(t % 8)};
    const ContactResult r = collide(PlaneShape{Vec3::Zero(), Vec3::UnitZ()}, s);
    EXPECT_TRUE(r.touching);
    // Four corners equally deep: soft depth kappa depth, gain kappa (soft_depth.h).
    EXPECT_NEAR(r.depth, SoftDepth::kappa * depth, 1e-13);
    EXPECT_NEAR(r.gain, SoftDepth::kappa, 1e-12);
    EXPECT_LT(r.twist.norm(), 1e-12);
    EXPECT_NEAR(r.point.x(), c.x(), 1e-12);
    EXPECT_NEAR(r.point.y(), c.y(), 1e-12);
    EXPECT_NEAR(r.point.z(), -0.5 * depth, 1e-13);
  }
}

TEST(Analytic, TiltedPolytopeDeepestVertexAndWeightedPoint) {
  Rng rng(44);
  const auto box = testing::box_hull(Vec3(1, 0.7, 0.4));
  const auto blob = testing::random_blob_hull(rng, 500);
  for (int t = 0; t < 2000; ++t) {
    const auto& hull = t % 2 ? box : blob;
    PlaneShape p{rng.unit_vector(), rng.unit_vector()};
    PolytopeShape s{&hull.poly, rng.rotation().toRotationMatrix(), Vec3::Zero(), rng.uniform(0.5, 2), 0};
    const auto v0 = testing::world_vertices(s);
    const double lowest = -testing::support_value(v0, -p.normal);
    s.pos = p.point - lowest * p.normal + rng.uniform(-0.3, 0.1) * s.scale * p.normal;
    s.hint = static_cast<Index>(rng.uniform() * static_cast<double>(hull.poly.size()));
    const auto v = testing::world_vertices(s);
    // Brute force: heights, deepest vertex and the soft depth of those below:
    // D = kappa S_{k+1}/S_k, g_i = kappa d_i^{k-1} ((k+1) d_i S_k - k S_{k+1})/S_k^2,
    // the point at the g-weighted centroid across the normal, halfway down at
    // the d^k-weighted one along it; the point contact at PD unless D > PD
    // and sum g > 0.
    constexpr int k = SoftDepth::kPower;
    double hmin = 1e300, sk = 0, sk1 = 0;
    for (const Vec3& x : v) {
      const double h = (x - p.point).dot(p.normal);
      hmin = std::min(hmin, h);
      if (h < 0) sk += std::pow(-h, k), sk1 += std::pow(-h, k + 1);
    }
    Vec3 xg = Vec3::Zero(), xk = Vec3::Zero();
    double sg = 0;
    for (const Vec3& x : v) {
      const double d = -(x - p.point).dot(p.normal);
      if (d <= 0) continue;
      const double g = SoftDepth::kappa * std::pow(d, k - 1) * ((k + 1) * d * sk - k * sk1) / (sk * sk);
      xg += g * x, sg += g, xk += std::pow(d, k) * (x + 0.5 * d * p.normal);
    }
    const ContactResult r = collide(p, s);
    ASSERT_EQ(r.touching, -hmin > 0);
    ASSERT_EQ(r.normal, p.normal);
    if (!r.touching) continue;
    const double soft = sk > 0 ? SoftDepth::kappa * sk1 / sk : 0;
    if (soft > -hmin && sg > 0) {
      ASSERT_NEAR(r.depth, soft, 1e-12);
      ASSERT_NEAR(r.gain, sg, 1e-9);
      xg /= sg, xk /= sk;
      const Vec3 expect = xg - (xg - xk).dot(p.normal) * p.normal;
      ASSERT_LT((r.point - expect).norm(), 1e-9) << "case " << t;
    } else {
      ASSERT_NEAR(r.depth, -hmin, 1e-12);
      ASSERT_EQ(r.gain, 1.0);
      ASSERT_NEAR((r.point - p.point).dot(p.normal), 0.5 * hmin, 1e-12);
    }
  }
}

}  // namespace
}  // namespace grainlab
