// Closed-form narrowphase: sphere-sphere, plane-sphere, plane-polytope.
#include "collision/narrowphase.h"
#include "collision/soft_depth.h"
#include "collision/sphere_pairs.h"
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

// Four pairs at once give each pair the bits it gets alone (collide(), which
// fills every lane with it): a world of spheres' narrowphase and the table's
// routine agree whatever lane a pair falls in. Coincident centres included.
TEST(Analytic, SpherePairsLanesAreIndependent) {
  Rng rng(43);
  int touching = 0;
  for (int t = 0; t < 500; ++t) {
    SphereShape a[4], b[4];
    SphereXYZR pa[4], pb[4];
    for (int l = 0; l < 4; ++l) {
      a[l] = SphereShape{rng.unit_vector() * 1e-2, rng.uniform(0.5, 1.5) * 1e-3};
      const double gap = t % 7 == l ? 0.0 : rng.uniform(0.1, 3) * 1e-3;
      b[l] = SphereShape{a[l].pos + gap * rng.unit_vector(), rng.uniform(0.5, 1.5) * 1e-3};
      pa[l] = a[l].pos.data(), pb[l] = b[l].pos.data();
    }
    SpherePairsOut out;
    sphere_pairs(pa, pb, out);
    for (int l = 0; l < 4; ++l) {
      const ContactResult lane = sphere_pair_result(out, l), alone = collide(a[l], b[l]);
      EXPECT_EQ(lane.touching, alone.touching);
      EXPECT_EQ(lane.depth, alone.depth) << "pair " << t << " lane " << l;
      EXPECT_EQ(lane.normal, alone.normal);
      EXPECT_EQ(lane.point, alone.point);
      EXPECT_TRUE(lane.normal.allFinite());
      touching += lane.touching;
    }
  }
  EXPECT_GT(touching, 200);
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
  constexpr int k = SoftDepth::kPower;
  Rng rng(43);
  for (int t = 0; t < 200; ++t) {
    const double depth = rng.uniform(1e-6, 0.1);
    const double yaw = rng.uniform(0, 6.28);
    const Vec3 c(rng.uniform(-5, 5), rng.uniform(-5, 5), 0.5 - depth);
    PolytopeShape s{&box.poly, Eigen::AngleAxisd(yaw, Vec3::UnitZ()).toRotationMatrix(), c, 1,
                    static_cast<Index>(t % 8)};
    const ContactResult r = collide(PlaneShape{Vec3::Zero(), Vec3::UnitZ()}, s);
    EXPECT_TRUE(r.touching);
    // The edges below the plane (soft_depth.h): the bottom face's 12 m of
    // edges at depth d, and the 4 vertical edges from d at the corner to 0 a
    // height d up: S_j = 12 d^j + 4 d^{j+1}/(j+1), D = kappa S_{k+1}/S_k,
    // gain = kappa ((k+1) S_k^2 - k S_{k+1} S_{k-1}) / S_k^2. The point is the
    // d^k-weighted centroid of the edges' points: z = -S_{k+1} / S_k.
    const double d = depth;
    const auto S = [&](int j) { return 12 * std::pow(d, j) + 4 * std::pow(d, j + 1) / (j + 1); };
    EXPECT_NEAR(r.depth, SoftDepth::kappa * S(k + 1) / S(k), 1e-13);
    EXPECT_NEAR(r.gain, SoftDepth::kappa * ((k + 1) * S(k) * S(k) - k * S(k + 1) * S(k - 1)) / (S(k) * S(k)), 1e-12);
    EXPECT_LT(r.twist.norm(), 1e-12);
    EXPECT_NEAR(r.point.x(), c.x(), 1e-12);
    EXPECT_NEAR(r.point.y(), c.y(), 1e-12);
    EXPECT_NEAR(r.point.z(), -S(k + 1) / S(k), 1e-13);
  }
}

// Brute force of the plane's soft depth: the part below the plane of every
// edge of the hull cut into 4000 pieces, each at its midpoint's depth
// (midpoint rule: relative error ~1e-7 to 1e-6), against the engine's exact
// integral (Gauss-Legendre) of the edges below the plane.
TEST(Analytic, TiltedPolytopeEdgesBelowThePlaneByBruteForce) {
  Rng rng(44);
  const auto box = testing::box_hull(Vec3(1, 0.7, 0.4));
  const auto blob = testing::random_blob_hull(rng, 60);
  constexpr int k = SoftDepth::kPower, pieces = 4000;
  int soft_cases = 0;
  for (int t = 0; t < 300; ++t) {
    const auto& hull = t % 2 ? box : blob;
    PlaneShape p{rng.unit_vector(), rng.unit_vector()};
    PolytopeShape s{&hull.poly, rng.rotation().toRotationMatrix(), Vec3::Zero(), rng.uniform(0.5, 2), 0};
    const auto v0 = testing::world_vertices(s);
    const double lowest = -testing::support_value(v0, -p.normal);
    s.pos = p.point - lowest * p.normal + rng.uniform(-0.3, 0.1) * s.scale * p.normal;
    s.hint = static_cast<Index>(rng.uniform() * static_cast<double>(hull.poly.size()));
    const auto v = testing::world_vertices(s);
    double hmin = 1e300;
    for (const Vec3& x : v) hmin = std::min(hmin, (x - p.point).dot(p.normal));
    double sk = 0, sk1 = 0, skm = 0;  // S_k, S_{k+1}, S_{k-1}
    Vec3 xg = Vec3::Zero(), xk = Vec3::Zero();
    double sg = 0;
    const auto each_piece = [&](const auto& f) {
      for (Index a = 0; a < static_cast<Index>(hull.poly.size()); ++a)
        for (const Index* it = hull.poly.neighbours_begin(a); it != hull.poly.neighbours_end(a); ++it) {
          if (*it < a || !hull.poly.is_edge(it)) continue;
          // The part below the plane, [x0, x1], cut into `pieces`.
          const double d0 = -(v[a] - p.point).dot(p.normal), d1 = -(v[*it] - p.point).dot(p.normal);
          if (d0 <= 0 && d1 <= 0) continue;
          const double t0 = d0 > 0 ? 0 : d0 / (d0 - d1), t1 = d1 > 0 ? 1 : d0 / (d0 - d1);
          const Vec3 x0 = v[a] + t0 * (v[*it] - v[a]), x1 = v[a] + t1 * (v[*it] - v[a]);
          const double len = (x1 - x0).norm() / pieces;
          for (int i = 0; i < pieces; ++i) {
            const Vec3 x = x0 + (i + 0.5) / pieces * (x1 - x0);
            const double d = -(x - p.point).dot(p.normal);
            if (d > 0) f(x, d, len);
          }
        }
    };
    each_piece([&](const Vec3&, double d, double len) {
      sk += len * std::pow(d, k), sk1 += len * std::pow(d, k + 1), skm += len * std::pow(d, k - 1);
    });
    each_piece([&](const Vec3& x, double d, double len) {
      const double g = len * SoftDepth::kappa * std::pow(d, k - 1) * ((k + 1) * d * sk - k * sk1) / (sk * sk);
      xg += g * x, sg += g, xk += len * std::pow(d, k) * x;
    });
    const ContactResult r = collide(p, s);
    ASSERT_EQ(r.touching, -hmin > 0);
    ASSERT_EQ(r.normal, p.normal);
    if (!r.touching) continue;
    ASSERT_GT(sk, 0) << "case " << t;  // touching: some edge is below
    if (!(sg > 0)) continue;               // the point contact stays (soft_depth.h)
    ++soft_cases;
    const double soft = SoftDepth::kappa * sk1 / sk;
    ASSERT_NEAR(r.depth, soft, 1e-5 * soft) << "case " << t;
    ASSERT_NEAR(r.gain, sg, 1e-5 * sg) << "case " << t;
    xg /= sg, xk /= sk;
    const Vec3 expect = xg - (xg - xk).dot(p.normal) * p.normal;
    ASSERT_LT((r.point - expect).norm(), 1e-5 * s.scale) << "case " << t;
  }
  EXPECT_GT(soft_cases, 150);
}

}  // namespace
}  // namespace grainlab
