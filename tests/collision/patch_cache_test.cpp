// The contact features kept between calls (patch_cache.h) against the patch
// found from scratch, on random hull pairs moving as DEM pairs do: the same
// bits at every call, whether the cache was reused, refilled or skipped,
// and reused on most calls of a slowly moving pair.
#include "collision/gjk.h"
#include "collision/narrowphase.h"
#include "collision/patch_cache.h"
#include "core/rng.h"
#include "test_shapes.h"

#include <gtest/gtest.h>

#include <cstring>

using namespace grainlab;
using namespace grainlab::testing;

namespace {

// Bit for bit (memcmp of every field the contact law reads).
bool same_bits(const ContactResult& x, const ContactResult& y) {
  const auto eq = [](const auto& p, const auto& q) { return std::memcmp(&p, &q, sizeof(p)) == 0; };
  return x.touching == y.touching && eq(x.depth, y.depth) && eq(x.normal, y.normal) && eq(x.point, y.point) &&
         eq(x.spread, y.spread) && eq(x.gain, y.gain) && eq(x.twist, y.twist);
}

// A random touching pair, 1e-3 of its size deep; u: from A towards B.
BlobPair touching_pair(Rng& rng, int run, Vec3& u) {
  BlobPair p;
  if (run % 3 == 2) {  // flat faces on flat faces
    p.ha = jittered_box_hull(rng, 60, 1e-3, Vec3(1, 0.8, 0.5));
    p.hb = jittered_box_hull(rng, 60, 1e-3, Vec3(0.7, 0.9, 0.5));
    p.a = PolytopeShape{&p.ha.poly, Mat3::Identity(), Vec3(1e-2, 0, 0), 1e-3, 0};
    p.b = PolytopeShape{&p.hb.poly, Eigen::AngleAxisd(rng.uniform(0, 3), Vec3::UnitZ()).toRotationMatrix(),
                        Vec3(1e-2, 0, 1e-3), 1e-3, 0};
    const double gap = p.b.support(-Vec3::UnitZ()).z() - p.a.support(Vec3::UnitZ()).z();
    p.b.pos.z() -= gap + 1e-6;
    u = Vec3::UnitZ();
  } else {
    p = make_blob_pair(rng, run % 3 == 0 ? 60 : 600, -1e-5, u);
    p.a.poly = &p.ha.poly, p.b.poly = &p.hb.poly;  // (the copy's own hulls)
    const ContactResult apart = gjk_epa(p.a, p.b, u);
    p.b.pos += (apart.depth - 1e-6) * u;
  }
  return p;
}

}  // namespace

// B drifts (slightly into A) and turns a little every call, and every 25
// calls jumps sideways by 1e-3 of its size or twists about the normal by
// 1e-2 rad, far past any skin the cache sized from the drift. A twist about
// the normal keeps every height along it, and so the candidate sets: a
// cache that ignored the motion bound gives other bits there.
TEST(PatchCache, CachedFeaturesGiveTheBitsOfThePatchFoundFromScratchAsPairsMove) {
  Rng rng(4242);
  long calls = 0, reused = 0;
  for (int run = 0; run < 24; ++run) {
    Vec3 u;
    BlobPair p = touching_pair(rng, run, u);
    p.a.poly = &p.ha.poly, p.b.poly = &p.hb.poly;  // (the copy's own hulls)
    const Vec3 drift = 4e-9 * rng.unit_vector() - 4e-9 * u;
    const Mat3 spin = Eigen::AngleAxisd(5e-6, rng.unit_vector()).toRotationMatrix();
    PatchCache kept;
    Vec3 dir = u;
    for (int step = 0; step < 100; ++step) {
      const Vec3 side = rng.unit_vector();
      const bool jump = step % 25 == 24;
      p.b.pos += jump && step % 50 == 24 ? Vec3(1e-6 * (side - side.dot(u) * u).normalized()) : drift;
      p.b.rot = (jump && step % 50 == 49 ? Mat3(Eigen::AngleAxisd(1e-2, u).toRotationMatrix()) : spin) * p.b.rot;
      const ContactResult r = gjk_epa(p.a, p.b, dir);
      if (!r.touching) continue;
      ContactResult cold = r, warm = r;
      contact_patch(p.a, p.b, cold);
      const std::uint32_t uses = kept.use_count;
      contact_patch(p.a, p.b, warm, &kept);
      ASSERT_TRUE(same_bits(warm, cold)) << "run " << run << " step " << step << ": depth " << warm.depth
                                         << " against " << cold.depth;
      ++calls;
      reused += kept.use_count == uses + 1;
    }
  }
  EXPECT_GT(calls, 1500);
  EXPECT_GT(reused, calls * 3 / 4) << "the cache should serve most calls (" << reused << " of " << calls << ")";
}

// A pair whose candidate sets change every call or two (a grain pressed in
// fast, as on landing) stops filling: the back-off leaves most calls plain.
TEST(PatchCache, APairPressedInFastBacksOff) {
  Rng rng(77);
  Vec3 u;
  BlobPair p = touching_pair(rng, 1, u);
  p.a.poly = &p.ha.poly, p.b.poly = &p.hb.poly;
  PatchCache kept;
  Vec3 dir = u;
  int calls = 0;
  for (int step = 0; step < 200; ++step) {
    p.b.pos -= 2e-7 * u;  // 2e-4 of the size a call
    const ContactResult r = gjk_epa(p.a, p.b, dir);
    if (!r.touching) continue;
    ContactResult cold = r, warm = r;
    contact_patch(p.a, p.b, cold);
    contact_patch(p.a, p.b, warm, &kept);
    ASSERT_TRUE(same_bits(warm, cold)) << "step " << step;
    ++calls;
  }
  const int fills = static_cast<int>(kept.fill_count);
  EXPECT_EQ(calls, 200);
  EXPECT_LT(fills, calls / 4) << fills << " fills in " << calls << " calls";
}

TEST(PatchCache, CopiesStartColdMovesKeep) {
  PatchCacheSlot a;
  a.get()->uses = 5;
  PatchCacheSlot b = a;
  EXPECT_EQ(b.peek(), nullptr);
  PatchCacheSlot c = std::move(a);
  ASSERT_NE(c.peek(), nullptr);
  EXPECT_EQ(c.peek()->uses, 5u);
}
