// Contact point of two polytopes touching face to face: the centroid of the
// overlap patch, continuous as one body tilts (not a witness point that jumps
// across the patch).
#include "collision/narrowphase.h"
#include "test_shapes.h"

#include "collision/soft_depth.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace grainlab;
using namespace grainlab::testing;

namespace {

// Lowest world height of a placed polytope.
double lowest(const PolytopeShape& s) {
  double z = 1e300;
  for (const Vec3& v : world_vertices(s)) z = std::min(z, v.z());
  return z;
}

}  // namespace

TEST(ContactPatch, FacesFindFacePlanes) {
  const TestHull box = box_hull(Vec3(1, 2, 3));
  EXPECT_EQ(box.poly.planes().size(), 6u);
  for (Index v = 0; v < 8; ++v) EXPECT_EQ(box.poly.planes_end(v) - box.poly.planes_begin(v), 3);
}

TEST(ContactPatch, OffsetFaceContactPushesAtOverlapCentroid) {
  const TestHull big = box_hull(Vec3(5e-3, 5e-3, 5e-3));
  const double delta = 1e-6;
  struct Case {
    Vec3 half_top, offset, centroid;
  };
  // Small box inside the big face: overlap = its footprint. Equal boxes offset
  // diagonally: overlap [-1, 5] x [-2, 5] mm.
  const Case cases[] = {{Vec3(2e-3, 2e-3, 2e-3), Vec3(2e-3, 1e-3, 0), Vec3(2e-3, 1e-3, 0)},
                        {Vec3(5e-3, 5e-3, 5e-3), Vec3(4e-3, 3e-3, 0), Vec3(2e-3, 1.5e-3, 0)}};
  for (const Case& c : cases) {
    const TestHull top = box_hull(c.half_top);
    const PolytopeShape a{&big.poly, Mat3::Identity(), Vec3::Zero(), 1.0};
    const PolytopeShape b{&top.poly, Mat3::Identity(),
                          c.offset + Vec3(0, 0, 5e-3 + c.half_top.z() - delta), 1.0};
    for (bool warm : {false, true}) {
      Vec3 dir = warm ? Vec3(0, 0, 1) : Vec3(0.3, 0.2, 1);
      const ContactResult r = collide_convex(a, b, dir, warm);
      ASSERT_TRUE(r.touching);
      // Soft depth of edges equally deep: kappa delta, gain kappa
      // (soft_depth.h), up to the top box's four vertical edges, inside for
      // a length delta: relative O(delta / perimeter) ~ 1e-4 at most here.
      EXPECT_NEAR(r.depth, SoftDepth::kappa * delta, 1e-4 * delta);
      EXPECT_NEAR(r.gain, SoftDepth::kappa, 1e-4);
      EXPECT_NEAR(r.point.x(), c.centroid.x(), 1e-4) << "warm " << warm;
      EXPECT_NEAR(r.point.y(), c.centroid.y(), 1e-4) << "warm " << warm;
      // On the line of action at the points' d^k-weighted centroid: between
      // the two surfaces.
      EXPECT_GE(r.point.z(), 5e-3 - delta - 1e-12);
      EXPECT_LE(r.point.z(), 5e-3 + 1e-12);
      EXPECT_GT(r.spread, 1e-6);  // patch of mm size: spread ~ mm^2
    }
  }
}

TEST(ContactPatch, PointMovesContinuouslyAsTheTopBoxTilts) {
  const TestHull big = box_hull(Vec3(5e-3, 5e-3, 5e-3));
  const TestHull top = box_hull(Vec3(2e-3, 2e-3, 2e-3));
  const double delta = 1e-6, face = 4e-3;
  for (bool warm : {false, true}) {
    Vec3 dir(0, 0, 1);
    Vec3 last = Vec3::Zero();
    bool first = true;
    double worst = 0;
    for (int i = -400; i <= 400; ++i) {
      const double theta = 1e-6 * i;  // +-4e-4 rad: face contact to edge contact and back
      const Mat3 rot = Eigen::AngleAxisd(theta, Vec3(0.6, 0.8, 0)).toRotationMatrix();
      PolytopeShape b{&top.poly, rot, Vec3(1e-3, -1e-3, 0), 1.0};
      b.pos.z() += 5e-3 - delta - lowest(b);
      const PolytopeShape a{&big.poly, Mat3::Identity(), Vec3::Zero(), 1.0};
      if (!warm) dir = Vec3(0.1 * std::sin(i), 0.1 * std::cos(i), 1);
      const ContactResult r = collide_convex(a, b, dir, warm);
      ASSERT_TRUE(r.touching);
      if (!first) worst = std::max(worst, (r.point - last).norm());
      last = r.point;
      first = false;
    }
    EXPECT_LT(worst, 0.05 * face) << "warm " << warm;
  }
}
