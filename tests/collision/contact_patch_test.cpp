// Contact point of two polytopes touching face to face: the centroid of the
// overlap patch, continuous as one body tilts (not a witness point that jumps
// across the patch).
#include "collision/narrowphase.h"
#include "test_shapes.h"

#include "collision/gjk.h"
#include "collision/soft_depth.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

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

namespace {

// A box of half extents `half` whose faces are each a cloud of points pushed
// in or out by up to `jitter` of the size: hulled, many nearly coplanar
// triangles, like the flat faces of a 1000-face angular grain.
TestHull jittered_box_hull(Rng& rng, int points_per_face, double jitter, const Vec3& half) {
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

// The contact of the pair by brute force, from the definition in patch.cpp:
// every edge of each shape, against the planes of the other's faces through
// its vertices beyond the first shape's supporting plane along the normal;
// along an edge the lower envelope of those planes' distances, found by
// splitting the edge at every crossing of two lines and every zero and
// taking the lowest line in the middle of each part.
ContactResult brute_force_patch(const PolytopeShape& a, const PolytopeShape& b, const ContactResult& r) {
  const Vec3 n = r.normal;
  double top_a = -1e300, bot_b = 1e300;
  for (const Vec3& v : world_vertices(a)) top_a = std::max(top_a, n.dot(v));
  for (const Vec3& v : world_vertices(b)) bot_b = std::min(bot_b, n.dot(v));
  SoftDepth soft(b.pos);
  const auto side = [&](const PolytopeShape& s, const PolytopeShape& o, bool o_below, double level, double sign) {
    std::vector<Index> planes;
    for (Index v = 0; v < static_cast<Index>(o.poly->size()); ++v) {
      const double h = n.dot(o.point(v));
      if (o_below ? !(h < level) : !(h > level)) continue;
      for (const Index* k = o.poly->planes_begin(v); k != o.poly->planes_end(v); ++k)
        if (std::find(planes.begin(), planes.end(), *k) == planes.end()) planes.push_back(*k);
    }
    const auto local = [&](const Vec3& x) -> Vec3 { return o.rot.transpose() * (x - o.pos) / o.scale; };
    for (Index v = 0; v < static_cast<Index>(s.poly->size()); ++v)
      for (const Index* it = s.poly->neighbours_begin(v); it != s.poly->neighbours_end(v); ++it) {
        if (*it < v || !s.poly->is_edge(it)) continue;
        const Vec3 p = s.point(v), q = s.point(*it), pl = local(p), ql = local(q);
        std::vector<double> d0, d1;  // the lines at t = 0 and 1 (o's local units)
        for (const Index k : planes) {
          const auto& P = o.poly->planes()[k];
          d0.push_back(P.c - P.m.dot(pl));
          d1.push_back(P.c - P.m.dot(ql));
        }
        std::vector<double> cuts{0, 1};
        for (std::size_t i = 0; i < planes.size(); ++i) {
          if (d0[i] != d1[i]) cuts.push_back(d0[i] / (d0[i] - d1[i]));
          for (std::size_t j = 0; j < i; ++j) {
            const double den = (d0[i] - d1[i]) - (d0[j] - d1[j]);
            if (den != 0) cuts.push_back((d0[i] - d0[j]) / den);
          }
        }
        std::sort(cuts.begin(), cuts.end());
        for (std::size_t c = 0; c + 1 < cuts.size(); ++c) {
          const double t0 = std::max(cuts[c], 0.0), t1 = std::min(cuts[c + 1], 1.0);
          if (!(t1 > t0 + 1e-13)) continue;
          const double tm = 0.5 * (t0 + t1);
          std::size_t best = 0;
          for (std::size_t i = 1; i < planes.size(); ++i)
            if (d0[i] + (d1[i] - d0[i]) * tm < d0[best] + (d1[best] - d0[best]) * tm) best = i;
          const auto at = [&](double t) { return (d0[best] + (d1[best] - d0[best]) * t) * o.scale; };
          if (!(at(tm) > 0)) continue;
          soft.add_linear_piece(p + t0 * (q - p), p + t1 * (q - p), at(t0), at(t1),
                                sign * (o.rot * o.poly->planes()[planes[best]].m));
        }
      }
  };
  side(a, b, true, top_a, -1.0);   // A's edges in B (the reaction on B)
  side(b, a, false, bot_b, 1.0);   // B's edges in A
  ContactResult out = r;
  soft.finish(out, n);
  return out;
}

}  // namespace

// The fast patch (collected vertices, one plane per vertex to class it, the
// lines an edge's envelope can use, 4 planes at a time) gives the brute
// force's contact on random pairs: irregular blobs of 8 to 600 vertices at
// random poses, and flat faces of nearly coplanar triangles pressed on each
// other, slightly tilted (the angular grains' costly case).
TEST(ContactPatch, MatchesTheBruteForceEnvelopeOnRandomPairs) {
  Rng rng(1207);
  int compared = 0, flat = 0;
  for (int run = 0; run < 48; ++run) {
    Vec3 u;
    BlobPair p;
    const bool flat_faces = run % 2 == 1;
    if (flat_faces) {
      const double L = 1e-3;
      p.ha = jittered_box_hull(rng, 60, 1e-3, Vec3(1, 0.8, 0.5));
      p.hb = jittered_box_hull(rng, 60, 1e-3, Vec3(0.7, 0.9, 0.5));
      const Mat3 tilt = Eigen::AngleAxisd(rng.uniform(0, 2e-3), Vec3(rng.uniform(-1, 1), rng.uniform(-1, 1), 0).normalized())
                            .toRotationMatrix();
      p.a = PolytopeShape{&p.ha.poly, Mat3::Identity(), Vec3(1e-2, 0, 0), L, 0};
      p.b = PolytopeShape{&p.hb.poly, tilt * Eigen::AngleAxisd(rng.uniform(0, 3), Vec3::UnitZ()).toRotationMatrix(),
                          Vec3(1e-2 + rng.uniform(-3e-4, 3e-4), rng.uniform(-3e-4, 3e-4), 1e-3), L, 0};
      const double gap = p.b.support(-Vec3::UnitZ()).z() - p.a.support(Vec3::UnitZ()).z();
      p.b.pos.z() -= gap + rng.uniform(2e-7, 2e-6);
      u = Vec3::UnitZ();
    } else {
      const int nverts = run % 6 == 0 ? 8 : run % 6 == 2 ? 60 : 600;
      p = make_blob_pair(rng, nverts, -1e-5, u);
      p.a.poly = &p.ha.poly, p.b.poly = &p.hb.poly;  // (the copy's own hulls)
      Vec3 n = u;
      const ContactResult apart = gjk_epa(p.a, p.b, n);
      p.b.pos += (apart.depth - rng.uniform(1e-7, 3e-5)) * n;
    }
    Vec3 dir = u;
    const ContactResult r = gjk_epa(p.a, p.b, dir);
    if (!r.touching) continue;
    ContactResult fast = r;
    contact_patch(p.a, p.b, fast);
    const ContactResult brute = brute_force_patch(p.a, p.b, r);
    ASSERT_GT(fast.gain, 0) << "run " << run;
    const double depth = brute.depth, L = p.b.scale;
    EXPECT_NEAR(fast.depth, depth, 1e-9 * depth) << "run " << run;
    EXPECT_NEAR(fast.gain, brute.gain, 1e-9 * brute.gain) << "run " << run;
    EXPECT_LT((fast.normal - brute.normal).norm(), 1e-9) << "run " << run;
    EXPECT_LT((fast.point - brute.point).norm(), 1e-9 * L) << "run " << run;
    EXPECT_LT((fast.twist - brute.twist).norm(), 1e-9 * L * (1 + brute.twist.norm() / L)) << "run " << run;
    ++compared;
    flat += flat_faces;
  }
  EXPECT_GE(compared, 40);
  EXPECT_GE(flat, 20);
}
