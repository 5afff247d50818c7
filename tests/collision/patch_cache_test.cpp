// The contact patch kept between steps (patch_cache.h) against the patch
// found from scratch, on random hull pairs moving as DEM pairs do: the same
// bits at every step, whether the kept patch was reused or refilled, and
// reused on most steps.
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

// A box of half extents `half` whose faces are clouds of points pushed in by
// up to `jitter`: many nearly coplanar triangles (flat faces pressed on each
// other: the envelope's hardest case, several lines near the lowest).
TestHull jittered_box(Rng& rng, int points_per_face, double jitter, const Vec3& half) {
  std::vector<Vec3> pts;
  for (int ax = 0; ax < 3; ++ax)
    for (int side = -1; side <= 1; side += 2)
      for (int i = 0; i < points_per_face; ++i) {
        Vec3 p(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
        p[ax] = side * (1 + rng.uniform(-jitter, 0));
        pts.push_back(p.cwiseProduct(half));
      }
  return convex_hull(pts);
}

}  // namespace

TEST(PatchCache, KeptPatchGivesTheBitsOfAPatchFoundFromScratchAsPairsMove) {
  Rng rng(4242);
  long steps = 0, reused = 0, refilled = 0;
  for (int run = 0; run < 24; ++run) {
    BlobPair p;
    Vec3 u;
    if (run % 3 == 2) {  // flat faces on flat faces
      p.ha = jittered_box(rng, 60, 1e-3, Vec3(1, 0.8, 0.5));
      p.hb = jittered_box(rng, 60, 1e-3, Vec3(0.7, 0.9, 0.5));
      p.a = PolytopeShape{&p.ha.poly, Mat3::Identity(), Vec3(1e-2, 0, 0), 1e-3, 0};
      p.b = PolytopeShape{&p.hb.poly, Eigen::AngleAxisd(rng.uniform(0, 3), Vec3::UnitZ()).toRotationMatrix(),
                          Vec3(1e-2, 0, 1e-3), 1e-3, 0};
      const double gap = p.b.support(-Vec3::UnitZ()).z() - p.a.support(Vec3::UnitZ()).z();
      p.b.pos.z() -= gap + 1e-6;
      u = Vec3::UnitZ();
    } else {
      p = make_blob_pair(rng, run % 3 == 0 ? 60 : 600, -1e-5, u);
      p.a.poly = &p.ha.poly, p.b.poly = &p.hb.poly;  // (the copy's own hulls)
      const ContactResult apart = gjk_epa(p.a, p.b, u);  // u: from A towards B
      p.b.pos += (apart.depth - 1e-6) * u;                // 1e-3 of the size deep
    }
    // Each step B drifts (slightly into A: B lies beyond A along u) and
    // turns by a few 1e-6 of its size, and every 25 steps jumps sideways by
    // 1e-3 of it (past any margin: the cache must be refilled).
    const Vec3 drift = 4e-9 * rng.unit_vector() - 4e-9 * u;
    const Mat3 spin = Eigen::AngleAxisd(5e-6, rng.unit_vector()).toRotationMatrix();
    PatchCache kept;
    Vec3 dir = u;
    for (int step = 0; step < 100; ++step) {
      const Vec3 side = rng.unit_vector();
      p.b.pos += step % 25 == 24 ? Vec3(1e-6 * (side - side.dot(u) * u).normalized()) : drift;
      p.b.rot = spin * p.b.rot;
      const ContactResult r = gjk_epa(p.a, p.b, dir);
      if (!r.touching) continue;
      ContactResult cold = r, warm = r;
      contact_patch(p.a, p.b, cold);
      const bool was_filled = kept.filled;
      const Mat3 fill_pose = kept.to_o[0];
      contact_patch(p.a, p.b, warm, &kept);
      ASSERT_TRUE(same_bits(warm, cold)) << "run " << run << " step " << step << ": depth " << warm.depth
                                         << " against " << cold.depth;
      ++steps;
      if (was_filled && kept.to_o[0] == fill_pose)
        ++reused;
      else
        ++refilled;
    }
  }
  EXPECT_GT(steps, 1500);
  EXPECT_GT(reused, steps / 2) << "the kept patch should serve most steps (" << reused << " of " << steps << ")";
  EXPECT_GT(refilled, 100) << "the jumps should refill it";
}

TEST(PatchCache, CopiesOwnTheirPatch) {
  PatchCacheSlot a;
  a.get()->margin[0] = 1;
  PatchCacheSlot b = a;
  b.get()->margin[0] = 2;
  EXPECT_EQ(a.get()->margin[0], 1);
  EXPECT_NE(a.get(), b.get());
  PatchCacheSlot c = std::move(b);
  EXPECT_EQ(c.get()->margin[0], 2);
}
