// The shape-pair table: every grain and wall pair the World meets has a
// routine; a pair served by a flipped registration gives exactly (bit for
// bit) the direct routine's result with the normal negated and the cache
// mirrored; a pair of kinds with no routine is refused.
#include "collision/dispatch.h"
#include "test_shapes.h"

#include <gtest/gtest.h>

#include <stdexcept>

using namespace grainlab;

TEST(Dispatch, EveryGrainPairAndWallGrainPairHasARoutine) {
  const ShapeKind grains[] = {ShapeKind::Sphere, ShapeKind::Polytope, ShapeKind::Compound};
  for (ShapeKind a : grains) {
    for (ShapeKind b : grains) EXPECT_TRUE(has_pair_routine(a, b));
    EXPECT_TRUE(has_pair_routine(ShapeKind::Plane, a));
    EXPECT_TRUE(has_pair_routine(ShapeKind::Box, a));
  }
  EXPECT_FALSE(has_pair_routine(ShapeKind::Plane, ShapeKind::Box));  // walls never meet walls
}

TEST(Dispatch, FlippedPairIsTheDirectRoutineMirrored) {
  Rng rng(7);
  const grainlab::testing::TestHull hull = grainlab::testing::random_blob_hull(rng, 60);
  const Mat3 rot = Quat(Eigen::AngleAxisd(0.3, Vec3(1, 2, 3).normalized())).toRotationMatrix();
  const Quat q = Quat::Identity();
  const PosedShape poly = grainlab::testing::posed_polytope(hull.poly, rot, q, Vec3(0.1, -0.2, 0.05), 1.3);
  PosedShape sphere;
  sphere.kind = ShapeKind::Sphere;
  sphere.radius = 0.4;
  sphere.rot = &rot;
  sphere.q = &q;
  int touching = 0;
  for (int k = 0; k < 50; ++k) {
    sphere.pos = poly.pos + Vec3(rng.uniform(-1.5, 1.5), rng.uniform(-1.5, 1.5), rng.uniform(-1.5, 1.5));
    PairCache direct{sphere.pos - poly.pos, 0, 3, false, {}}, flipped{poly.pos - sphere.pos, 3, 0, false, {}};
    SubContact rd[kMaxSubContacts], rf[kMaxSubContacts];
    ASSERT_EQ(collide_shapes(sphere, poly, direct, rd), 1);
    ASSERT_EQ(collide_shapes(poly, sphere, flipped, rf), 1);
    EXPECT_EQ(rd[0].geo.touching, rf[0].geo.touching);
    EXPECT_EQ(rd[0].geo.depth, rf[0].geo.depth);
    EXPECT_EQ(rd[0].geo.normal, Vec3(-rf[0].geo.normal));
    EXPECT_EQ(rd[0].geo.point, rf[0].geo.point);
    EXPECT_EQ(direct.dir, Vec3(-flipped.dir));
    EXPECT_EQ(direct.hint_b, flipped.hint_a);
    touching += rd[0].geo.touching;
  }
  EXPECT_GT(touching, 5);
  EXPECT_LT(touching, 45);
}

TEST(Dispatch, PairWithoutARoutineIsRefused) {
  const Quat q = Quat::Identity();
  const Mat3 rot = Mat3::Identity();
  PosedShape plane, box;
  plane.kind = ShapeKind::Plane;
  plane.q = &q;
  box.kind = ShapeKind::Box;
  box.rot = &rot;
  PairCache cache;
  SubContact out[kMaxSubContacts];
  EXPECT_THROW(collide_shapes(plane, box, cache, out), std::logic_error);
}
