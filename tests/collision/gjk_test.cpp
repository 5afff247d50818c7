// GJK/EPA against exact references: spheres, box-sphere, box-box (SAT and
// brute-force distance), random hull pairs (support-function minimum).
#include "collision/gjk.h"
#include "collision/narrowphase.h"
#include "collision/test_shapes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

namespace grainlab {
namespace {

double angle(const Vec3& a, const Vec3& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

// Spheres through the GJK/EPA template against the closed form.
TEST(GjkEpa, SpheresMatchClosedForm) {
  Rng rng(21);
  double max_err[2] = {0, 0}, max_ang[2] = {0, 0};  // [separated, overlapping]
  for (int t = 0; t < 4000; ++t) {
    const Vec3 off = rng.unit_vector() * (t % 2 ? 1e-2 : 1.0);
    const double ra = rng.uniform(0.5, 1.5) * 1e-3, rb = rng.uniform(0.5, 1.5) * 1e-3;
    SphereShape a{off, ra};
    // Gap from deep overlap to separated, mostly shallow.
    const double u = rng.uniform();
    const double depth = u < 0.5 ? rng.uniform(1e-4, 1e-2) * ra
                                 : (u < 0.8 ? rng.uniform(-0.5, 0.5) * ra : rng.uniform(-1, 1) * 1e-6 * ra);
    const Vec3 n = rng.unit_vector();
    SphereShape b{off + (ra + rb - depth) * n, rb};
    Vec3 dir = t % 3 ? rng.unit_vector() : n;
    GjkEpaInfo info;
    const ContactResult r = gjk_epa(a, b, dir, &info);
    const ContactResult ex = collide(a, b);
    ASSERT_TRUE(std::isfinite(r.depth) && r.normal.allFinite() && r.point.allFinite());
    const int k = ex.depth > 0 ? 1 : 0;
    const double err = std::abs(r.depth - ex.depth) / ra;
    const double ang = angle(r.normal, ex.normal);
    max_err[k] = std::max(max_err[k], err);
    if (std::abs(ex.depth) > 1e-7 * ra) max_ang[k] = std::max(max_ang[k], ang);
    ASSERT_LT(err, 1e-6) << "case " << t << " depth " << ex.depth << " got " << r.depth << " gjk " << info.gjk_iterations << " epa " << info.epa_iterations << " conv " << info.epa_converged << " used " << info.used_epa;
    if (std::abs(ex.depth) > 1e-7 * ra) {
      // Tighter for separated and shallow (DEM) overlaps than for deep ones.
      ASSERT_LT(ang, ex.depth < 1e-2 * ra ? 1e-4 : 1e-3) << "case " << t << " depth " << ex.depth;
    }
    ASSERT_EQ(dir, r.normal);
  }
  std::printf("spheres: separated depth err %.2e ang %.2e; overlapping depth err %.2e ang %.2e\n",
              max_err[0], max_ang[0], max_err[1], max_ang[1]);
}

// --- boxes -----------------------------------------------------------------

Vec3 box_axis(const BoxShape& b, int i) { return b.rot.col(i); }

// h_C(u) = h_A(u) + h_B(-u) for two boxes, exactly.
double box_h(const BoxShape& b, const Vec3& u) {
  double h = b.pos.dot(u);
  for (int i = 0; i < 3; ++i) h += b.half[i] * std::abs(box_axis(b, i).dot(u));
  return h;
}
double overlap_along(const BoxShape& a, const BoxShape& b, const Vec3& u) {
  return box_h(a, u) + box_h(b, -u);
}

// Separating-axis reference: the penetration depth of two boxes is the
// smallest support overlap over the 15 candidate axes (both signs).
struct SatResult {
  double depth, second;
  Vec3 normal;
};
SatResult sat(const BoxShape& a, const BoxShape& b) {
  std::vector<Vec3> axes;
  for (int i = 0; i < 3; ++i) axes.push_back(box_axis(a, i)), axes.push_back(box_axis(b, i));
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const Vec3 c = box_axis(a, i).cross(box_axis(b, j));
      if (c.norm() > 1e-6) axes.push_back(c.normalized());
    }
  SatResult r{1e300, 1e300, Vec3::UnitZ()};
  for (const Vec3& ax : axes)
    for (const Vec3& u : {ax, Vec3(-ax)}) {
      const double o = overlap_along(a, b, u);
      if (o < r.depth) {
        r.second = r.depth;
        r.depth = o, r.normal = u;
      } else if (o < r.second && (u - r.normal).norm() > 1e-9) {
        r.second = o;
      }
    }
  return r;
}

Vec3 closest_on_box(const BoxShape& b, const Vec3& p) {
  const Vec3 q = b.rot.transpose() * (p - b.pos);
  return b.pos + b.rot * q.cwiseMax(-b.half).cwiseMin(b.half);
}
std::vector<Vec3> box_corners(const BoxShape& b) {
  std::vector<Vec3> out;
  for (int i = 0; i < 8; ++i)
    out.push_back(b.pos + b.rot * Vec3((i & 1) ? b.half.x() : -b.half.x(),
                                       (i & 2) ? b.half.y() : -b.half.y(),
                                       (i & 4) ? b.half.z() : -b.half.z()));
  return out;
}
// Squared distance between segments (Ericson 5.1.9), both of positive length.
double segment_distance2(const Vec3& p1, const Vec3& q1, const Vec3& p2, const Vec3& q2) {
  const Vec3 d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
  const double a = d1.dot(d1), e = d2.dot(d2), f = d2.dot(r), c = d1.dot(r), b = d1.dot(d2);
  const double den = a * e - b * b;
  double s = den > 1e-14 * a * e ? std::clamp((b * f - c * e) / den, 0.0, 1.0) : 0.0;
  double t = (b * s + f) / e;
  if (t < 0) t = 0, s = std::clamp(-c / a, 0.0, 1.0);
  else if (t > 1) t = 1, s = std::clamp((b - c) / a, 0.0, 1.0);
  return (p1 + s * d1 - p2 - t * d2).squaredNorm();
}
// Exact box-box distance: vertex-to-box both ways and all edge pairs.
double box_distance(const BoxShape& a, const BoxShape& b) {
  const auto ca = box_corners(a), cb = box_corners(b);
  double d2 = 1e300;
  for (const Vec3& p : ca) d2 = std::min(d2, (p - closest_on_box(b, p)).squaredNorm());
  for (const Vec3& p : cb) d2 = std::min(d2, (p - closest_on_box(a, p)).squaredNorm());
  for (int i = 0; i < 8; ++i)
    for (int bit : {1, 2, 4}) {
      if (i & bit) continue;
      for (int j = 0; j < 8; ++j)
        for (int bj : {1, 2, 4}) {
          if (j & bj) continue;
          d2 = std::min(d2, segment_distance2(ca[i], ca[i | bit], cb[j], cb[j | bj]));
        }
    }
  return std::sqrt(d2);
}

TEST(GjkEpa, BoxBoxMatchesSatAndExactDistance) {
  Rng rng(22);
  double max_pen = 0, max_pen_ang = 0, max_sep = 0;
  int n_pen = 0, n_sep = 0;
  for (int t = 0; t < 3000; ++t) {
    const double L = 1e-3;
    BoxShape a{rng.rotation().toRotationMatrix(), rng.unit_vector() * 1e-2,
               L * Vec3(rng.uniform(0.3, 1), rng.uniform(0.3, 1), rng.uniform(0.3, 1))};
    const Vec3 hb = L * Vec3(rng.uniform(0.3, 1), rng.uniform(0.3, 1), rng.uniform(0.3, 1));
    const auto hull = testing::box_hull(hb);
    PolytopeShape b{&hull.poly, rng.rotation().toRotationMatrix(), Vec3::Zero(), 1, 0};
    BoxShape bb{b.rot, Vec3::Zero(), hb};
    // Along a random direction, place B so that its support overlap is delta.
    const Vec3 u = rng.unit_vector();
    const double delta = (t % 2 ? rng.uniform(1e-4, 1e-2) : rng.uniform(-0.3, 0.3)) * L;
    const double tpos = overlap_along(a, bb, u) - delta;
    b.pos = bb.pos = a.pos + tpos * u;
    Vec3 dir = rng.unit_vector();
    // GJK/EPA itself (collide_convex replaces a face contact by the plane's soft depth).
    const ContactResult r = gjk_epa(a, b, dir);
    ASSERT_TRUE(std::isfinite(r.depth) && r.normal.allFinite() && r.point.allFinite());
    const SatResult s = sat(a, bb);
    if (s.depth > 0) {
      ++n_pen;
      ASSERT_TRUE(r.touching);
      const double err = std::abs(r.depth - s.depth) / L;
      max_pen = std::max(max_pen, err);
      ASSERT_LT(err, 1e-9) << "case " << t;
      // The returned normal achieves the depth.
      ASSERT_NEAR(overlap_along(a, bb, r.normal), r.depth, 1e-10 * L);
      if (s.second - s.depth > 1e-6 * L) {
        max_pen_ang = std::max(max_pen_ang, angle(r.normal, s.normal));
        ASSERT_LT(angle(r.normal, s.normal), 1e-6) << "case " << t;
      }
    } else {
      ++n_sep;
      const double dist = box_distance(a, bb);
      ASSERT_FALSE(r.touching && dist > 1e-9 * L);
      const double err = std::abs(-r.depth - dist) / L;
      max_sep = std::max(max_sep, err);
      ASSERT_LT(err, 1e-9) << "case " << t << " dist " << dist;
      ASSERT_NEAR(overlap_along(a, bb, r.normal), -dist, 1e-9 * L);
    }
  }
  std::printf("box-box: %d penetrating (depth err %.2e L, normal %.2e rad), %d separated (err %.2e L)\n",
              n_pen, max_pen, max_pen_ang, n_sep, max_sep);
}

// Box-sphere (a curved Minkowski sum) against the exact closed form.
TEST(GjkEpa, BoxSphereMatchesClosedForm) {
  Rng rng(23);
  double max_err = 0, max_ang = 0, max_deep = 0;
  for (int t = 0; t < 3000; ++t) {
    const double L = 1e-3;
    BoxShape a{rng.rotation().toRotationMatrix(), rng.unit_vector() * 1e-2,
               L * Vec3(rng.uniform(0.3, 1), rng.uniform(0.3, 1), rng.uniform(0.3, 1))};
    const double rad = rng.uniform(0.3, 1) * L;
    // Target the sphere centre at a random point near the surface of the box.
    const Vec3 target = closest_on_box(a, a.pos + 3 * L * rng.unit_vector());
    const Vec3 n0 = rng.unit_vector();
    const double gap = (t % 2 ? -rng.uniform(1e-4, 1e-2) : rng.uniform(-0.3, 0.3)) * L;
    SphereShape b{target + (rad + gap) * n0, rad};
    // Exact: the closest box point to the centre, or the nearest face if inside.
    const Vec3 q = a.rot.transpose() * (b.pos - a.pos);
    const Vec3 cl = q.cwiseMax(-a.half).cwiseMin(a.half);
    double depth;
    Vec3 n;
    if ((q - cl).norm() > 0) {
      depth = rad - (q - cl).norm();
      n = a.rot * (q - cl).normalized();
    } else {
      int k = 0;
      (a.half - q.cwiseAbs()).minCoeff(&k);
      depth = rad + a.half[k] - std::abs(q[k]);
      n = a.rot.col(k) * (q[k] >= 0 ? 1.0 : -1.0);
    }
    Vec3 dir = rng.unit_vector();
    const ContactResult r = collide_convex(a, b, dir);
    ASSERT_TRUE(std::isfinite(r.depth) && r.normal.allFinite());
    const double err = std::abs(r.depth - depth) / L;
    const bool shallow = std::abs(depth) < 1e-2 * L;
    max_err = std::max(max_err, shallow ? err : 0.0);
    max_deep = std::max(max_deep, shallow ? 0.0 : err);
    ASSERT_LT(err, shallow ? 1e-6 : 1e-4) << "case " << t << " depth " << depth;
    if (std::abs(depth) > 1e-6 * L && depth < 1e-2 * L) {
      max_ang = std::max(max_ang, angle(r.normal, n));
      ASSERT_LT(angle(r.normal, n), 1e-3) << "case " << t << " depth " << depth;
    }
  }
  std::printf("box-sphere: shallow depth err %.2e L, normal %.2e rad; deep depth err %.2e L\n",
              max_err, max_ang, max_deep);
}

// --- random hull pairs ------------------------------------------------------

struct Placed {
  testing::TestHull hull;
  PolytopeShape shape;
  std::vector<Vec3> verts;
};

Placed place(testing::TestHull h, Rng& rng, double size, const Vec3& pos) {
  Placed p{std::move(h), {}, {}};
  p.shape = PolytopeShape{nullptr, rng.rotation().toRotationMatrix(), pos, size, 0};
  return p;
}
void finish(Placed& p) {
  p.shape.poly = &p.hull.poly;
  p.verts = testing::world_vertices(p.shape);
}
double hull_h(const Placed& p, const Vec3& u) { return testing::support_value(p.verts, u); }
double hull_overlap(const Placed& a, const Placed& b, const Vec3& u) {
  return hull_h(a, u) + hull_h(b, -u);
}
// Largest signed distance of x outside the hull's face planes (<= 0 inside).
double outside(const Placed& p, const Vec3& x) {
  double m = -1e300;
  for (const auto& f : p.hull.faces) {
    const Vec3 a = p.verts[f[0]], b = p.verts[f[1]], c = p.verts[f[2]];
    const Vec3 n = (b - a).cross(c - a).normalized();
    m = std::max(m, n.dot(x - a));
  }
  return m;
}

// Exact penetration depth of two polytopes: min of h_C over the face normals
// of both and the cross products of all edge pairs (the face normals of C).
double exact_depth(const Placed& a, const Placed& b) {
  std::vector<Vec3> cand;
  std::vector<Vec3> ea, eb;
  for (const Placed* p : {&a, &b}) {
    for (const auto& f : p->hull.faces) {
      const Vec3 x = p->verts[f[0]], y = p->verts[f[1]], z = p->verts[f[2]];
      cand.push_back((y - x).cross(z - x).normalized());
      auto& e = p == &a ? ea : eb;
      e.push_back(y - x), e.push_back(z - y), e.push_back(x - z);
    }
  }
  for (const Vec3& x : ea)
    for (const Vec3& y : eb) {
      const Vec3 c = x.cross(y);
      if (c.norm() > 1e-12 * x.norm() * y.norm()) cand.push_back(c.normalized());
    }
  double best = 1e300;
  for (const Vec3& u : cand) {
    best = std::min(best, hull_overlap(a, b, u));
    best = std::min(best, hull_overlap(a, b, -u));
  }
  return best;
}

void run_hull_pairs(int cases, int nverts, bool exact, std::uint64_t seed) {
  Rng rng(seed);
  double max_err = 0, max_sep = 0, max_wit = 0;
  int n_pen = 0, n_sep = 0;
  for (int t = 0; t < cases; ++t) {
    const double L = 1e-3;
    Placed a = place(testing::random_blob_hull(rng, nverts), rng, L, rng.unit_vector() * 1e-2);
    Placed b = place(testing::random_blob_hull(rng, nverts), rng, L * rng.uniform(0.5, 1.5), Vec3::Zero());
    finish(a);
    finish(b);
    const Vec3 u = rng.unit_vector();
    const double delta = (t % 3 ? rng.uniform(1e-4, 1e-2) : rng.uniform(-0.3, 0.5)) * L;
    const double tpos = hull_overlap(a, b, u) - delta;
    b.shape.pos = a.shape.pos + tpos * u;
    finish(b);
    Vec3 dir = t % 2 ? rng.unit_vector() : u;
    GjkEpaInfo info;
    const ContactResult r = gjk_epa(a.shape, b.shape, dir, &info);
    ASSERT_TRUE(std::isfinite(r.depth) && r.normal.allFinite() && r.point.allFinite());
    ASSERT_NEAR(r.normal.norm(), 1, 1e-12);
    // The normal achieves the depth...
    const double tol = 1e-9 * L;
    ASSERT_NEAR(hull_overlap(a, b, r.normal), r.depth, tol) << "case " << t;
    if (r.touching) {
      ++n_pen;
      // ...and nothing does better: sampled directions, around the normal, exact set.
      for (int k = 0; k < 300; ++k) {
        const Vec3 v = k < 150 ? rng.unit_vector()
                               : (r.normal + rng.uniform(0, 0.1) * rng.unit_vector()).normalized();
        ASSERT_GE(hull_overlap(a, b, v), r.depth - tol) << "case " << t;
      }
      if (exact) {
        const double ex = exact_depth(a, b);
        max_err = std::max(max_err, std::abs(ex - r.depth) / L);
        ASSERT_NEAR(r.depth, ex, tol) << "case " << t;
      }
      // The contact point lies between the two bodies' surfaces: inside both, up to the depth.
      max_wit = std::max({max_wit, outside(a, r.point), outside(b, r.point)});
      ASSERT_LE(outside(a, r.point), r.depth + tol);
      ASSERT_LE(outside(b, r.point), r.depth + tol);
    } else {
      ++n_sep;
      // Separated: the normal separates, with gap = distance; witnesses lie on
      // the shapes, their distance is the gap.
      const double dist = -r.depth;
      const Vec3 pa = r.point - 0.5 * dist * r.normal, pb = r.point + 0.5 * dist * r.normal;
      max_sep = std::max({max_sep, std::abs(outside(a, pa)), std::abs(outside(b, pb))});
      ASSERT_NEAR(outside(a, pa), 0, tol) << "case " << t;
      ASSERT_NEAR(outside(b, pb), 0, tol) << "case " << t;
      ASSERT_NEAR(r.normal.dot(pa), hull_h(a, r.normal), tol);
      ASSERT_NEAR(-r.normal.dot(pb), hull_h(b, -r.normal), tol);
    }
  }
  std::printf("hulls n=%d: %d penetrating (exact depth err %.2e L), %d separated (witness err %.2e L), point %.2e L\n",
              nverts, n_pen, max_err, n_sep, max_sep / 1e-3, max_wit / 1e-3);
}

TEST(GjkEpa, SmallHullPairsMatchExactDepth) { run_hull_pairs(600, 16, true, 24); }
TEST(GjkEpa, LargeHullPairsMinimiseSupportOverlap) { run_hull_pairs(1000, 400, false, 25); }

TEST(GjkEpa, WarmStartGivesSameAnswer) {
  Rng rng(26);
  for (int t = 0; t < 500; ++t) {
    const double L = 1e-3;
    Placed a = place(testing::random_blob_hull(rng, 200), rng, L, rng.unit_vector() * 1e-2);
    Placed b = place(testing::random_blob_hull(rng, 200), rng, L, Vec3::Zero());
    finish(a);
    const Vec3 u = rng.unit_vector();
    finish(b);
    b.shape.pos = a.shape.pos + (hull_overlap(a, b, u) - rng.uniform(-1e-3, 1e-2) * L) * u;
    Vec3 dir = rng.unit_vector();
    const ContactResult r1 = gjk_epa(a.shape, b.shape, dir);
    const Vec3 dir1 = dir;
    const ContactResult r2 = gjk_epa(a.shape, b.shape, dir);
    ASSERT_EQ(r1.touching, r2.touching);
    ASSERT_NEAR(r1.depth, r2.depth, 1e-10 * L) << "case " << t;
    ASSERT_LT(angle(r1.normal, r2.normal), 1e-6);
    // The contact point may move within a flat contact patch, but stays midway
    // between the two support planes.
    ASSERT_NEAR(r1.normal.dot(r1.point - r2.point), 0, 1e-9 * L);
    ASSERT_EQ(dir1, r1.normal);
  }
}

TEST(GjkEpa, TouchingAndDegenerateInputsStayFinite) {
  const auto hull = testing::box_hull(Vec3(1, 1, 1));
  PolytopeShape a{&hull.poly, Mat3::Identity(), Vec3::Zero(), 1, 0};
  PolytopeShape b = a;
  for (const Vec3& off : {Vec3(2, 0, 0), Vec3(2, 2, 0), Vec3(2, 2, 2), Vec3(0, 0, 0), Vec3(1, 0, 0),
                          Vec3(2, 0.5, 0.25)}) {
    b.pos = off;
    for (const Vec3& d0 : {Vec3(1, 0, 0), Vec3(0, 0, 0), Vec3(0, 1, 0), Vec3(-1, -1, -1)}) {
      Vec3 dir = d0;
      const ContactResult r = collide_convex(a, b, dir);
      ASSERT_TRUE(std::isfinite(r.depth) && r.normal.allFinite() && r.point.allFinite());
      ASSERT_NEAR(r.normal.norm(), 1, 1e-12);
      const double expect = 2 - off.cwiseAbs().maxCoeff();  // exact for these offsets
      ASSERT_NEAR(r.depth, expect, 1e-10) << off.transpose() << " dir " << d0.transpose();
    }
  }
}

}  // namespace
}  // namespace grainlab
