// Warm-started translated-GJK penetration against EPA on random hull pairs.
#include "collision/penetration.h"
#include "core/rng.h"
#include "test_shapes.h"

#include <gtest/gtest.h>

using namespace grainlab;

namespace {

using grainlab::testing::make_blob_pair;
using Pair = grainlab::testing::BlobPair;

// Largest signed distance of x outside the placed hull's face planes (<= 0 inside).
double outside(const grainlab::testing::TestHull& h, const PolytopeShape& s, const Vec3& x) {
  const std::vector<Vec3> v = grainlab::testing::world_vertices(s);
  double m = -1e300;
  for (const auto& f : h.faces) {
    const Vec3 n = (v[f[1]] - v[f[0]]).cross(v[f[2]] - v[f[0]]).normalized();
    m = std::max(m, n.dot(x - v[f[0]]));
  }
  return m;
}

double overlap_along(const Pair& p, const Vec3& n) { return n.dot(p.a.support(n) - p.b.support(-n)); }

}  // namespace

TEST(WarmPenetration, MatchesEpaFromANearbyDirection) {
  Rng rng(5);
  int used = 0, touching = 0;
  for (int t = 0; t < 4000; ++t) {
    const int nverts = t % 2 ? 400 : 40;
    Vec3 u;
    Pair p = make_blob_pair(rng, nverts, rng.uniform(2e-6, 3e-5), u);  // DEM-size overlaps
    Vec3 dir_epa = u;
    const ContactResult epa = gjk_epa(p.a, p.b, dir_epa);
    if (!epa.touching) continue;
    ++touching;
    // Start a little off the optimal normal, as last step's normal would be.
    Vec3 dir = (epa.normal + rng.uniform(0, 0.03) * rng.unit_vector()).normalized();
    ContactResult warm;
    if (!warm_penetration(p.a, p.b, dir, warm)) continue;
    ++used;
    const double tol = 1e-9 * 1e-3;
    ASSERT_TRUE(warm.touching) << "case " << t;
    EXPECT_NEAR(warm.depth, epa.depth, tol) << "case " << t;
    EXPECT_NEAR(overlap_along(p, warm.normal), warm.depth, tol) << "the normal must achieve the depth";
    // The point lies between the surfaces (on a flat patch it may differ from EPA's).
    EXPECT_LE(outside(p.ha, p.a, warm.point), warm.depth + tol) << "case " << t;
    EXPECT_LE(outside(p.hb, p.b, warm.point), warm.depth + tol) << "case " << t;
    EXPECT_EQ(dir, warm.normal);
  }
  EXPECT_GT(touching, 100);
  EXPECT_GT(used, 0.95 * touching) << "the fast path should conclude for nearly every warm case";
}

TEST(WarmPenetration, TracksAnApproachingPairStepByStep) {
  // B creeps into A as in a DEM run; the pair's direction is carried from step
  // to step (separated GJK normals first, then the penetration normals).
  Rng rng(9);
  for (int run = 0; run < 40; ++run) {
    Vec3 u;
    Pair p = make_blob_pair(rng, 300, -2e-6, u);  // starts 2 um apart
    Vec3 dir = u;
    const Vec3 step = -1e-7 * u + 2e-8 * rng.unit_vector();
    for (int i = 0; i < 80; ++i) {
      p.b.pos += step;
      ContactResult warm;
      Vec3 d_epa = dir;
      const ContactResult epa = gjk_epa(p.a, p.b, d_epa);
      if (warm_penetration(p.a, p.b, dir, warm)) {
        ASSERT_EQ(warm.touching, epa.touching) << "run " << run << " step " << i;
        if (warm.touching) {
          ASSERT_NEAR(warm.depth, epa.depth, 1e-12) << "run " << run << " step " << i;
        } else {
          // Clearly apart (penetration.h's shortcut): h_C along the kept
          // direction, a lower bound of the gap (-depth), not the gap itself:
          // the direction is the one GJK gave some steps before.
          ASSERT_GE(warm.depth, epa.depth - 1e-15) << "run " << run << " step " << i;
        }
      } else {
        ASSERT_FALSE(epa.touching && overlap_along(p, dir) > 0);
        dir = d_epa;  // what the narrowphase does: GJK's answer seeds the next step
      }
    }
  }
}

TEST(WarmPenetration, FromTheWrongWayRefusesOrAgreesWithEpa) {
  // Started across the pair (-u, where h_C is the pair's whole length), the
  // local iteration is far from the answer: it must hand the pair to EPA or
  // give an answer EPA's would not contradict. Never a contact of shapes that
  // are apart: an iteration that wandered for six steps and kept the least
  // positive h_C it saw reported one (depth 4.7e-5 m for shapes 4.6e-5 m
  // apart, on a pair Clang's argument order drew).
  Rng rng(3);
  int refused = 0, apart = 0;
  for (int t = 0; t < 300; ++t) {
    Vec3 u;
    Pair p = make_blob_pair(rng, 100, rng.uniform(-3e-5, 3e-5), u);
    Vec3 d_epa = u;
    const ContactResult epa = gjk_epa(p.a, p.b, d_epa);
    apart += !epa.touching;
    Vec3 dir = -u;
    ContactResult r;
    if (!warm_penetration(p.a, p.b, dir, r)) {
      ++refused;
      continue;
    }
    ASSERT_EQ(r.touching, epa.touching) << "case " << t << ": depth " << r.depth << ", EPA's " << epa.depth;
    EXPECT_GE(r.depth, epa.depth - 1e-15) << "case " << t << ": every direction's h_C bounds the depth from above";
  }
  EXPECT_GT(apart, 30);
  EXPECT_GT(refused, 270);
}
