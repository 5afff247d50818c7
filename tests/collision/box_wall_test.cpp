// A box wall against a faceted grain (routines_wall.cpp): a grain whose
// bounding sphere lies over one face of the box meets the box as that face's
// plane, without GJK. Checked on random poses against brute force (the
// deepest hull vertex behind the face) and against the GJK/EPA path; grains
// over an edge or a corner still take GJK/EPA.
#include "collision/dispatch.h"
#include "collision/narrowphase.h"
#include "test_shapes.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace grainlab;

namespace {

struct Wall {
  Quat q = Quat(Eigen::AngleAxisd(0.7, Vec3(1, -2, 0.5).normalized()));
  Mat3 rot = q.toRotationMatrix();
  Vec3 half = Vec3(2.0, 1.5, 0.8);  // m; a grain is about 1 across
  Vec3 pos = Vec3(0.2, -0.1, 0.4);

  PosedShape posed() const {
    PosedShape p;
    p.kind = ShapeKind::Box;
    p.geometry = &half;
    p.rot = &rot;
    p.q = &q;
    p.pos = pos;
    return p;
  }
};

}  // namespace

TEST(BoxWall, AGrainOverOneFaceMeetsThatFacesPlaneAsBruteForceAndGjkSay) {
  Rng rng(11);
  const grainlab::testing::TestHull hull = grainlab::testing::random_blob_hull(rng, 80);
  const Wall wall;
  const double scale = 0.5;
  const double r = scale * hull.poly.bounding_radius();
  int touching = 0, apart = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const Mat3 rot = Quat(Eigen::AngleAxisd(rng.uniform(0, 6.3), Vec3(rng.uniform(-1, 1), rng.uniform(-1, 1),
                                                                      rng.uniform(-1, 1)).normalized()))
                         .toRotationMatrix();
    const Quat qb(rot);
    // Over face k on side s: both other coordinates within the face less the
    // bounding radius; the centre from 0.3 r inside the face to 1.1 r outside.
    const int k = trial % 3, i = (k + 1) % 3, j = (k + 2) % 3;
    const double s = trial % 2 ? 1.0 : -1.0;
    Vec3 local;
    local[i] = rng.uniform(-1, 1) * (wall.half[i] - r);
    local[j] = rng.uniform(-1, 1) * (wall.half[j] - r);
    local[k] = s * (wall.half[k] + rng.uniform(-0.3, 1.1) * r);
    const PosedShape grain = grainlab::testing::posed_polytope(hull.poly, rot, qb, wall.pos + wall.rot * local, scale);

    PairCache cache{grain.pos - wall.pos, 0, 0, false, {}};
    SubContact out[kMaxSubContacts];
    ASSERT_EQ(collide_shapes(wall.posed(), grain, cache, out), 1);
    EXPECT_FALSE(cache.warm) << "trial " << trial << ": GJK ran for a grain over a face";

    // Brute force: the deepest vertex behind the face's plane.
    const Vec3 n = s * wall.rot.col(k);
    const Vec3 face_point = wall.pos + wall.half[k] * n;
    PolytopeShape pb{&hull.poly, rot, grain.pos, scale, 0};
    double deepest = -1e300;
    for (const Vec3& v : grainlab::testing::world_vertices(pb)) deepest = std::max(deepest, (face_point - v).dot(n));
    EXPECT_EQ(out[0].geo.touching, deepest > 0) << "trial " << trial;
    if (!out[0].geo.touching) {
      ++apart;
      continue;
    }
    ++touching;
    EXPECT_NEAR((out[0].geo.normal - n).norm(), 0, 1e-15) << "trial " << trial;
    EXPECT_GT(out[0].geo.depth, 0);  // the soft depth (soft_depth.h), not the deepest vertex's

    // The GJK/EPA path (cold) ends in the same face plane routine.
    Vec3 dir = grain.pos - wall.pos;
    PolytopeShape pg{&hull.poly, rot, grain.pos, scale, 0};
    const ContactResult g = collide_convex(BoxShape{wall.rot, wall.pos, wall.half}, pg, dir, false);
    ASSERT_TRUE(g.touching) << "trial " << trial;
    EXPECT_NEAR(g.depth, out[0].geo.depth, 1e-12 * r) << "trial " << trial;
    EXPECT_NEAR((g.normal - out[0].geo.normal).norm(), 0, 1e-9) << "trial " << trial;
    EXPECT_NEAR((g.point - out[0].geo.point).norm(), 0, 1e-12 * r) << "trial " << trial;
  }
  EXPECT_GT(touching, 50);
  EXPECT_GT(apart, 20);
}

TEST(BoxWall, AGrainOverAnEdgeTakesGjk) {
  Rng rng(12);
  const grainlab::testing::TestHull hull = grainlab::testing::random_blob_hull(rng, 80);
  const Wall wall;
  const Mat3 rot = Mat3::Identity();
  const Quat qb = Quat::Identity();
  // Centre just over the top face (axis 2), across its edge at x = +h_x.
  const double scale = 0.5;
  const PosedShape grain = grainlab::testing::posed_polytope(
      hull.poly, rot, qb, wall.pos + wall.rot * Vec3(wall.half.x(), 0, wall.half.z() + 0.1 * scale), scale);
  PairCache cache{grain.pos - wall.pos, 0, 0, false, {}};
  SubContact out[kMaxSubContacts];
  ASSERT_EQ(collide_shapes(wall.posed(), grain, cache, out), 1);
  EXPECT_TRUE(cache.warm);  // GJK/EPA ran
  EXPECT_TRUE(out[0].geo.touching);
}
