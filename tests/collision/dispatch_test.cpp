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

// A kind registered at run time gets the next free id and its name, and its
// routine serves both orders (the other flipped); a routine for a kind not
// registered is refused.
namespace {
int marked_routine(const PosedShape& a, const PosedShape&, PairCache&, PairCache*, SubContact* out) {
  out[0] = {};
  out[0].geo.normal = Vec3::UnitX();
  out[0].geo.depth = a.radius;
  return 1;
}
}  // namespace

TEST(Dispatch, RegisteredKindGetsTheNextIdAndItsRoutineServesBothOrders) {
  const int before = shape_kind_count();
  EXPECT_GE(before, kBuiltInShapeKinds);
  const ShapeKind k = register_shape_kind("marked");
  EXPECT_EQ(static_cast<int>(k), before);
  EXPECT_EQ(shape_kind_count(), before + 1);
  EXPECT_EQ(shape_kind_name(k), "marked");
  EXPECT_EQ(shape_kind_name(ShapeKind::Polytope), "polytope");
  EXPECT_FALSE(has_pair_routine(k, ShapeKind::Sphere));
  register_pair_routine(k, ShapeKind::Sphere, marked_routine, PairNeeds{.reads_cache = false});
  EXPECT_TRUE(has_pair_routine(k, ShapeKind::Sphere));
  EXPECT_TRUE(has_pair_routine(ShapeKind::Sphere, k));
  EXPECT_FALSE(pair_needs(ShapeKind::Sphere, k).reads_cache);
  PosedShape a, b;
  a.kind = k, a.radius = 0.25;
  b.kind = ShapeKind::Sphere, b.radius = 0.5;
  PairCache cache;
  SubContact out[kMaxSubContacts];
  ASSERT_EQ(collide_shapes(a, b, cache, out), 1);
  EXPECT_EQ(out[0].geo.depth, 0.25);
  EXPECT_EQ(out[0].geo.normal, Vec3::UnitX());
  ASSERT_EQ(collide_shapes(b, a, cache, out), 1);  // flipped: the marked shape is still the routine's a
  EXPECT_EQ(out[0].geo.depth, 0.25);
  EXPECT_EQ(out[0].geo.normal, -Vec3::UnitX());
  const auto unregistered = static_cast<ShapeKind>(kMaxShapeKinds - 1);
  EXPECT_THROW(register_pair_routine(unregistered, ShapeKind::Sphere, marked_routine, {}), std::logic_error);
}

// The needs the table declares (PairNeeds) hold for what its routines do:
// slots within kMaxSubContacts, a flipped pair needing what its direct one
// does, and a pair declared compact gives through collide_compact the bits
// of its table routine (after the caller's bounding-sphere test), without
// touching the cache it declares it does not read.
TEST(Dispatch, PairNeedsHoldForTheRoutines) {
  for (int a = 0; a < shape_kind_count(); ++a)
    for (int b = 0; b < shape_kind_count(); ++b) {
      const auto ka = static_cast<ShapeKind>(a), kb = static_cast<ShapeKind>(b);
      const PairNeeds& n = pair_needs(ka, kb);
      if (!has_pair_routine(ka, kb)) continue;
      EXPECT_GE(n.sub_contacts, 1);
      EXPECT_LE(n.sub_contacts, kMaxSubContacts);
      const PairNeeds& f = pair_needs(kb, ka);
      EXPECT_EQ(n.sub_contacts, f.sub_contacts);
      EXPECT_EQ(n.reads_cache, f.reads_cache);
      EXPECT_EQ(n.extra_caches, f.extra_caches);
      EXPECT_EQ(n.compact, f.compact);
    }
  Rng rng(11);
  int touching = 0, compact_pairs = 0;
  for (int k = 0; k < shape_kind_count(); ++k) {
    const auto kind = static_cast<ShapeKind>(k);
    if (!pair_needs(kind, kind).compact) continue;
    ++compact_pairs;
    for (int i = 0; i < 200; ++i) {
      const CompactPose pa{Vec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)), rng.uniform(0.1, 0.8)};
      const CompactPose pb{Vec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)), rng.uniform(0.1, 0.8)};
      PosedShape a, b;
      a.kind = b.kind = kind;
      a.pos = pa.x, a.radius = pa.radius;
      b.pos = pb.x, b.radius = pb.radius;
      PairCache cache;
      SubContact out[kMaxSubContacts];
      const ContactResult fast = collide_compact(pa, pb);
      const bool reach = (pb.x - pa.x).squaredNorm() <= (pa.radius + pb.radius) * (pa.radius + pb.radius);
      ASSERT_EQ(collide_shapes(a, b, cache, out), 1);
      EXPECT_EQ(cache.dir, PairCache{}.dir);
      EXPECT_EQ(cache.warm, false);
      EXPECT_EQ(fast.touching, out[0].geo.touching);
      if (!reach) continue;
      EXPECT_EQ(fast.depth, out[0].geo.depth);
      EXPECT_EQ(fast.normal, out[0].geo.normal);
      EXPECT_EQ(fast.point, out[0].geo.point);
      touching += fast.touching;
    }
  }
  EXPECT_GE(compact_pairs, 1);
  EXPECT_GT(touching, 20);
}
