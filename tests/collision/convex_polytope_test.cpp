// ConvexPolytope: construction checks and hill-climbing support queries
// against brute-force argmax.
#include "collision/shapes.h"
#include "collision/test_shapes.h"
#include "core/error.h"

#include <gtest/gtest.h>

namespace grainlab {
namespace {

using testing::support_value;

// Hill climbing from random starts gives the brute-force maximum of dot(v, d).
void check_support(const testing::TestHull& h, Rng& rng, int queries) {
  const ConvexPolytope& p = h.poly;
  for (int q = 0; q < queries; ++q) {
    Vec3 d = rng.unit_vector() * rng.uniform(1e-3, 1e3);
    if (q % 10 == 0) d = Vec3::Unit(q % 3) * (q % 20 == 0 ? 1.0 : -1.0);  // ties: whole faces
    const Index start = static_cast<Index>(rng.uniform() * static_cast<double>(p.size()));
    const Index k = p.support_index(d, start);
    ASSERT_GE(k, 0);
    ASSERT_LT(static_cast<std::size_t>(k), p.size());
    const double brute = support_value(p.vertices(), d);
    ASSERT_NEAR(p.vertex(k).dot(d), brute, 1e-13 * d.norm() * p.bounding_radius())
        << "query " << q << " from vertex " << start;
  }
}

TEST(ConvexPolytope, HillClimbMatchesBruteForceOnEllipsoidHulls) {
  Rng rng(11);
  for (int t = 0; t < 40; ++t) {
    const int n = t < 30 ? 4 + static_cast<int>(rng.uniform() * 200) : 1000;
    const auto h = testing::random_ellipsoid_hull(rng, n, 0.2, 2.0);
    ASSERT_EQ(h.poly.size(), static_cast<std::size_t>(n));  // all points extreme
    check_support(h, rng, 500);
  }
}

TEST(ConvexPolytope, HillClimbMatchesBruteForceOnIrregularHulls) {
  Rng rng(12);
  for (int t = 0; t < 40; ++t) {
    const auto h = testing::random_blob_hull(rng, 20 + static_cast<int>(rng.uniform() * 600));
    check_support(h, rng, 500);
  }
}

TEST(ConvexPolytope, HillClimbOnBoxesWithTies) {
  Rng rng(13);
  for (int t = 0; t < 50; ++t) {
    const Vec3 half(rng.uniform(0.1, 2), rng.uniform(0.1, 2), rng.uniform(0.1, 2));
    check_support(testing::box_hull(half), rng, 200);
  }
}

TEST(ConvexPolytope, BoundingRadiusAndWorldSupport) {
  const auto h = testing::box_hull(Vec3(1, 2, 3));
  EXPECT_DOUBLE_EQ(h.poly.bounding_radius(), std::sqrt(14.0));
  Rng rng(14);
  const auto e = testing::random_ellipsoid_hull(rng, 300);
  for (int t = 0; t < 200; ++t) {
    PolytopeShape s{&e.poly, rng.rotation().toRotationMatrix(), rng.unit_vector() * 10.0,
                    rng.uniform(0.5, 2.0), 0};
    const Vec3 d = rng.unit_vector();
    const Vec3 p = s.support(d);
    EXPECT_NEAR(p.dot(d), support_value(testing::world_vertices(s), d), 1e-12);
    EXPECT_LT((p - (s.pos + s.scale * (s.rot * e.poly.vertex(s.hint)))).norm(), 1e-13);
  }
}

TEST(ConvexPolytope, RejectsBadInput) {
  const std::vector<Vec3> v{Vec3(1, 0, 0), Vec3(0, 1, 0)};
  EXPECT_THROW(ConvexPolytope({}, {0}, {}), InputError);
  EXPECT_THROW(ConvexPolytope(v, {0, 1}, {1}), InputError);         // offsets too short
  EXPECT_THROW(ConvexPolytope(v, {0, 1, 2}, {1, 5}), InputError);   // index out of range
  EXPECT_THROW(ConvexPolytope(v, {0, 1, 3}, {1, 0}), InputError);   // offsets past the end
  EXPECT_NO_THROW(ConvexPolytope(v, {0, 1, 2}, {1, 0}));
  EXPECT_THROW(ConvexPolytope({Vec3(NAN, 0, 0)}, {0, 0}, {}), InputError);
}

}  // namespace
}  // namespace grainlab
