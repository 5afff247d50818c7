// GJK restarted from a pair's kept simplex (simplex_cache.h) against GJK/EPA
// from scratch, on random hull pairs moving as DEM pairs do: the same distance
// and depth, in fewer iterations, and the right answer from any kept indices.
#include "collision/narrowphase.h"
#include "collision/penetration.h"
#include "core/rng.h"
#include "test_shapes.h"

#include <gtest/gtest.h>

using namespace grainlab;

namespace {

using grainlab::testing::make_blob_pair;
using Pair = grainlab::testing::BlobPair;

// A small rotation about a random axis.
Mat3 turn(Rng& rng, double angle) {
  return Eigen::AngleAxisd(angle, rng.unit_vector()).toRotationMatrix();
}

}  // namespace

TEST(SimplexCache, GjkFromTheKeptSimplexGivesColdGjksDistanceInFewerIterations) {
  Rng rng(21);
  long cold_iterations = 0, kept_iterations = 0;
  int separated = 0;
  for (int run = 0; run < 30; ++run) {
    Vec3 u;
    Pair p = make_blob_pair(rng, run % 2 ? 600 : 60, -rng.uniform(1e-7, 2e-5), u);
    const Vec3 drift = 1e-8 * rng.unit_vector();
    const Mat3 spin = turn(rng, 2e-4);
    Vec3 dir_kept = u;
    SimplexCache kept;
    for (int step = 0; step < 60; ++step) {
      p.b.pos += drift;
      p.b.rot = spin * p.b.rot;
      Vec3 dir_cold = dir_kept;
      GjkEpaInfo cold_info, kept_info;
      const ContactResult cold = gjk_epa(p.a, p.b, dir_cold, &cold_info);
      const ContactResult r = gjk_epa(p.a, p.b, dir_kept, &kept_info, &kept);
      ASSERT_EQ(r.touching, cold.touching) << "run " << run << " step " << step;
      ASSERT_NEAR(r.depth, cold.depth, 1e-14) << "run " << run << " step " << step;
      if (cold.touching) {
        EXPECT_EQ(kept.n, 0) << "an overlap (EPA) leaves no simplex to keep";
        continue;
      }
      ++separated;
      EXPECT_GT(kept.n, 0);
      // GJK stops within 1e-12 of the shapes' size (2e-15 m) of the gap; the
      // normal is as sharp as that against the gap (>= 1e-7 m here).
      EXPECT_LT((r.normal - cold.normal).norm(), 1e-6) << "run " << run << " step " << step;
      if (step > 0) kept_iterations += kept_info.gjk_iterations, cold_iterations += cold_info.gjk_iterations;
    }
  }
  EXPECT_GT(separated, 1000);
  EXPECT_LT(3 * kept_iterations, cold_iterations)
      << "the kept simplex should spare most iterations (kept " << kept_iterations << ", cold "
      << cold_iterations << ")";
}

TEST(SimplexCache, WarmPenetrationFromTheKeptSimplexMatchesEpaStepByStep) {
  // B creeps into A while both turn a little, as in a DEM run; the direction
  // and the simplex are carried from step to step as the narrowphase does.
  Rng rng(33);
  int touching = 0, warm = 0, kept_face_above = 0;
  for (int run = 0; run < 40; ++run) {
    Vec3 u;
    Pair p = make_blob_pair(rng, 300, -2e-6, u);
    Vec3 n = u;
    const ContactResult start = gjk_epa(p.a, p.b, n);
    p.b.pos += (start.depth + 2e-6) * n;  // 2 um apart along the closest direction n
    Vec3 dir = n;
    SimplexCache kept;
    const Vec3 step = -1e-7 * n + 2e-8 * rng.unit_vector();
    const Mat3 spin = turn(rng, 2e-5);
    for (int i = 0; i < 80; ++i) {
      p.b.pos += step;
      p.a.rot = spin * p.a.rot;
      Vec3 d_epa = dir;
      const ContactResult epa = gjk_epa(p.a, p.b, d_epa);
      const ContactResult r = collide_convex(p.a, p.b, dir, i > 0, &kept);
      ASSERT_EQ(r.touching, epa.touching) << "run " << run << " step " << i;
      if (!epa.touching) continue;
      ++touching;
      // The contact's depth is the soft depth of the patch (soft_depth.h),
      // not PD; PD itself is checked against EPA through the same call
      // without a patch: warm_penetration with its own copy of the simplex.
      ContactResult pd;
      Vec3 d_pd = d_epa;
      SimplexCache copy = kept;
      if (warm_penetration(p.a, p.b, d_pd, pd, &copy)) {
        ++warm;
        // The kept face is a local answer (penetration.h): where the deepest
        // face of A - B changes to a neighbour at an angle, the kept face
        // stays while the origin's foot lies in it, an upper bound of the
        // depth (one step of this test, 0.09 % deep, under Clang's draw of
        // the pairs). Its h_C must still be the depth it reports.
        ASSERT_GE(pd.depth, epa.depth - 1e-12) << "run " << run;
        ASSERT_NEAR(pd.normal.dot(p.a.support(pd.normal) - p.b.support(-pd.normal)), pd.depth, 1e-12);
        if (std::abs(pd.depth - epa.depth) > 1e-12) {
          ++kept_face_above;
          EXPECT_LT(pd.depth - epa.depth, 1e-2 * epa.depth) << "run " << run;
        }
      }
      EXPECT_GT(r.depth, 0);
    }
  }
  EXPECT_GT(touching, 1000);
  EXPECT_GT(warm, 0.95 * touching);
  EXPECT_LE(kept_face_above, warm / 200) << "the kept face should agree with EPA but at rare switches of face";
}

TEST(SimplexCache, AnyKeptIndicesGiveTheRightDistance) {
  // Indices kept at another pose (B moved by up to 50 um and turned by
  // 0.05 rad: its closest feature has changed) or drawn at random only slow
  // GJK down: every A[i] - B[j] is a point of A - B. The other pose's
  // indices lie near the origin, so GJK does start from them.
  Rng rng(8);
  int separated = 0;
  for (int t = 0; t < 500; ++t) {
    Vec3 u;
    Pair p = make_blob_pair(rng, 200, rng.uniform(-3e-5, 3e-5), u);
    SimplexCache kept;
    if (t % 4 == 0) {
      kept.n = 1 + t % 3;
      for (int i = 0; i < 3; ++i)
        kept.a[i] = static_cast<Index>(rng.uniform() * p.ha.poly.size()),
        kept.b[i] = static_cast<Index>(rng.uniform() * p.hb.poly.size());
    } else {
      PolytopeShape elsewhere = p.b;
      elsewhere.pos += 5e-5 * rng.uniform() * rng.unit_vector() + 5e-5 * u;  // apart, so a simplex is kept
      elsewhere.rot = turn(rng, 0.05) * elsewhere.rot;
      Vec3 d = u;
      gjk_epa(p.a, elsewhere, d, nullptr, &kept);
    }
    Vec3 d1 = u, d2 = u;
    const ContactResult cold = gjk_epa(p.a, p.b, d1);
    const ContactResult r = gjk_epa(p.a, p.b, d2, nullptr, &kept);
    ASSERT_EQ(r.touching, cold.touching) << t;
    // GJK stops within 2e-15 m of the gap; EPA within 1e-10 of the size.
    EXPECT_NEAR(r.depth, cold.depth, cold.touching ? 1e-12 : 1e-14) << t;
    separated += !cold.touching;
  }
  EXPECT_GT(separated, 100);
}

TEST(SimplexCache, KeptFaceAnswersOnlyWhileItsPlaneStillSupportsTheShapes) {
  // A touching pair's kept triangle, then B turned by up to 0.05 rad: the
  // shortcut may answer only if the triangle still lies on the supporting
  // plane along its normal (its depth is then the triangle's own offset);
  // otherwise it must leave the pair to GJK.
  Rng rng(12);
  int answered = 0, refused = 0, agree = 0;
  for (int t = 0; t < 1500; ++t) {
    Vec3 u;
    Pair p = make_blob_pair(rng, 300, rng.uniform(2e-6, 2e-5), u);
    Vec3 dir = u;
    const ContactResult epa0 = gjk_epa(p.a, p.b, dir);
    if (!epa0.touching) continue;
    SimplexCache kept;
    ContactResult first;
    if (!warm_penetration(p.a, p.b, dir, first, &kept) || kept.n != 3) continue;
    p.b.rot = turn(rng, rng.uniform(0, 0.05)) * p.b.rot;
    ContactResult r;
    Vec3 d = dir;
    if (!penetration_detail::kept_face(p.a, p.b, kept, d, r)) {
      ++refused;
      continue;
    }
    ++answered;
    const double offset = r.normal.dot(p.a.point(kept.a[0]) - p.b.point(kept.b[0]));
    EXPECT_NEAR(r.depth, offset, 1e-15) << t;
    const std::vector<Vec3> va = grainlab::testing::world_vertices(p.a), vb = grainlab::testing::world_vertices(p.b);
    const double brute = grainlab::testing::support_value(va, r.normal) + grainlab::testing::support_value(vb, -r.normal);
    EXPECT_NEAR(r.depth, brute, 1e-15) << t;
    // A local fixed point, as warm_penetration's (see penetration.h): never
    // shallower than EPA's global one, nearly always the same.
    Vec3 d_epa = d;
    const double pd = gjk_epa(p.a, p.b, d_epa).depth;
    EXPECT_GT(r.depth, pd - 1e-12) << t;
    agree += std::abs(r.depth - pd) < 1e-12;
  }
  EXPECT_GT(answered, 50);
  EXPECT_GT(refused, 50);
  EXPECT_GT(agree, 0.95 * answered) << agree << " agree, " << answered << " answered, " << refused << " refused";
}

TEST(SimplexCache, SwappedNamesTheSamePointsForTheReversedPair) {
  SimplexCache s;
  s.n = 2;
  s.a[0] = 4, s.a[1] = 7, s.b[0] = 1, s.b[1] = 9;
  const SimplexCache r = s.swapped();
  EXPECT_EQ(r.n, 2);
  EXPECT_EQ(r.a[0], 1);
  EXPECT_EQ(r.a[1], 9);
  EXPECT_EQ(r.b[0], 4);
  EXPECT_EQ(r.b[1], 7);
}
