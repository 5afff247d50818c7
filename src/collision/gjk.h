// GJK distance and EPA penetration depth on support mappings.
//
// Pure geometry, templated on the two shapes: anything with
//   Vec3 support(const Vec3& d) const;  // a point maximising dot(p, d)
//   Vec3 center() const;                // a point strictly inside
// works (PolytopeShape, BoxShape, SphereShape, ...). Nothing is allocated.
//
// Both algorithms work on the Minkowski difference C = A - B, whose support
// point in direction d is s_C(d) = s_A(d) - s_B(-d). The shapes overlap iff the
// origin lies in C.
//
// GJK (separated shapes). It keeps a simplex of at most 4 points of C and v,
// the point of the simplex closest to the origin. Each step adds w = s_C(-v)
// and replaces the simplex by the smallest face of it that holds the new
// closest point. |v| is an upper bound of the distance and dot(v, w)/|v| a
// lower bound (the plane through w normal to v bounds C); it stops when the
// two agree to the tolerance, when |v| stops decreasing (rounding floor), or
// when the simplex encloses the origin (overlap). The closest points are
// p_A = sum lambda_i a_i and p_B = sum lambda_i b_i with the barycentric
// weights of v, and the normal (from A to B) is -v/|v|.
//
// EPA (overlapping shapes). Starting from a tetrahedron of C that holds the
// origin, it grows a convex polytope inside C: take the face closest to the
// origin (plane distance d, outward normal n), add w = s_C(n). d is a lower
// bound and h_C(n) = dot(n, w) = h_A(n) + h_B(-n) an upper bound of the
// penetration depth min_n h_C(n); it stops when they agree to the tolerance.
// Faces seen from w are removed (found by a walk over face adjacency, so the
// removed region is connected) and the hole is closed by a fan to w. The
// result is the smallest upper bound met and its direction, so moving B by
// depth*normal always separates the shapes exactly. Witness points are the
// barycentric combinations of the a_i and b_i at the closest face.
//
// Tolerances are relative to the size of C (estimated from the first support
// points), so results do not depend on units or on where the shapes are.
#pragma once

#include "collision/contact_result.h"
#include "collision/simplex_cache.h"

#include <algorithm>
#include <cmath>
#include <concepts>
#include <limits>

namespace grainlab {

// Optional diagnostics of one gjk_epa call.
struct GjkEpaInfo {
  int gjk_iterations = 0;
  int epa_iterations = 0;
  bool used_epa = false;
  bool epa_converged = false;  // false: stopped on capacity or degeneracy, best bound returned
  // Separated shapes: the final GJK simplex, points of C = A - B whose convex
  // hull holds the closest point to the origin.
  int simplex_size = 0;
  Vec3 simplex[4];
};

namespace gjk_detail {

inline constexpr double kGjkRelTol = 1e-12;    // distance tolerance / size of C
inline constexpr double kEpaRelTol = 1e-10;    // depth tolerance / size of C
inline constexpr double kTouchRelTol = 1e-11;  // |v| below this (times size) counts as contact
inline constexpr int kMaxGjkIterations = 128;

// A point of C = A - B with the two shape points it came from.
// For shapes with a hill-climbing hint (PolytopeShape), the hints the query
// ended on are kept too, so that a later query near this point can start there.
struct SupportPoint {
  Vec3 w, a, b;
  Index ha = 0, hb = 0;
};

template <class S>
concept HasHint = requires(const S& s) { s.hint = Index{0}; };
// Shapes whose support points are vertices that can be named by index
// (PolytopeShape): their simplex can be kept between calls (simplex_cache.h).
template <class S>
concept HasPoints = HasHint<S> && requires(const S& s, Index i) {
  { s.point(i) } -> std::convertible_to<Vec3>;
};

struct Simplex {
  SupportPoint p[4];
  double lambda[4];
  int n = 0;
};

// Closest point of the simplex to the origin, written to v; the simplex is
// reduced to the points that carry it, with their barycentric weights. Returns
// true when a non-degenerate tetrahedron contains the origin (v = 0).
bool reduce_simplex(Simplex& s, Vec3& v);

// Closest point of triangle (a, b, c) to the origin and its barycentric weights.
Vec3 closest_on_triangle(const Vec3& a, const Vec3& b, const Vec3& c, double l[3]);

// Expanding polytope with fixed capacity (no heap).
class Epa {
 public:
  static constexpr int kMaxVertices = 64;
  static constexpr int kMaxFaces = 128;

  struct Result {
    double depth = 0;
    Vec3 normal = Vec3::UnitZ();
    Vec3 pa = Vec3::Zero(), pb = Vec3::Zero();
    int iterations = 0;
    bool converged = false;
    bool valid = false;
  };

  // Runs EPA from tetrahedron t (which must hold the origin up to rounding).
  template <class Support, class Seed>
  Result run(const Support& support, const Seed& seed, const SupportPoint t[4], double tol);

 private:
  struct Face {
    int v[3];
    int adj[3];       // face across edge (v[i], v[i+1])
    int adj_edge[3];  // index of that edge in the neighbour
    Vec3 n;           // outward unit normal
    double dist;      // plane distance from the origin
    bool alive;
  };
  bool make_face(int f, int a, int b, int c);
  int new_face_slot();
  bool expand(int closest, int wi);
  void record(int f, double upper, Result& r) const;

  SupportPoint verts_[kMaxVertices];
  Face faces_[kMaxFaces];
  int free_[kMaxFaces];
  int nv_ = 0, nf_ = 0, nfree_ = 0;
};

template <class Support, class Seed>
Epa::Result Epa::run(const Support& support, const Seed& seed, const SupportPoint t[4], double tol) {
  Result r;
  nv_ = nf_ = nfree_ = 0;
  for (int i = 0; i < 4; ++i) verts_[i] = t[i];
  nv_ = 4;
  const double vol = (t[1].w - t[0].w).dot((t[2].w - t[0].w).cross(t[3].w - t[0].w));
  if (vol < 0) std::swap(verts_[1], verts_[2]);
  // Outward faces of a positively oriented tetrahedron 0123.
  static constexpr int kTet[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  for (int f = 0; f < 4; ++f) {
    if (!make_face(f, kTet[f][0], kTet[f][1], kTet[f][2])) return r;
  }
  nf_ = 4;
  for (int f = 0; f < 4; ++f) {
    for (int e = 0; e < 3; ++e) {
      const int u = faces_[f].v[e], w = faces_[f].v[(e + 1) % 3];
      for (int g = 0; g < 4; ++g)
        for (int h = 0; h < 3; ++h)
          if (faces_[g].v[h] == w && faces_[g].v[(h + 1) % 3] == u) {
            faces_[f].adj[e] = g;
            faces_[f].adj_edge[e] = h;
          }
    }
  }

  double best_upper = std::numeric_limits<double>::infinity();
  for (;;) {
    int closest = -1;
    double dmin = std::numeric_limits<double>::infinity();
    for (int f = 0; f < nf_; ++f)
      if (faces_[f].alive && faces_[f].dist < dmin) {
        dmin = faces_[f].dist;
        closest = f;
      }
    if (closest < 0) break;
    ++r.iterations;
    const Vec3 n = faces_[closest].n;
    seed(verts_[faces_[closest].v[0]]);
    const SupportPoint p = support(n);
    const double upper = n.dot(p.w);
    if (!r.valid || upper < best_upper) {
      best_upper = upper;
      record(closest, upper, r);
    }
    if (upper - dmin <= tol) {
      r.converged = true;
      break;
    }
    if (nv_ == kMaxVertices) break;
    verts_[nv_] = p;
    if (!expand(closest, nv_++)) break;
  }
  return r;
}

}  // namespace gjk_detail

// Distance (separated) or penetration (overlapping) of two convex support
// shapes. `dir` seeds the search (the last normal of this pair, or any
// non-zero vector) and receives the returned normal. For two shapes with
// named vertices, `simplex` (if given and not empty) is the simplex the
// pair's last call ended on: GJK starts from it instead of from the support
// point along dir, and it receives this call's final simplex (emptied when
// the shapes overlap).
template <class ShapeA, class ShapeB>
ContactResult gjk_epa(const ShapeA& a, const ShapeB& b, Vec3& dir, GjkEpaInfo* info = nullptr,
                      SimplexCache* simplex = nullptr) {
  using namespace gjk_detail;
  const auto support = [&](const Vec3& d) {
    SupportPoint p;
    p.a = a.support(d);
    p.b = b.support(-d);
    p.w = p.a - p.b;
    if constexpr (HasHint<ShapeA>) p.ha = a.hint;
    if constexpr (HasHint<ShapeB>) p.hb = b.hint;
    return p;
  };
  // Seeds the hill climbs at a known nearby support point (EPA face vertex).
  const auto seed = [&](const SupportPoint& p) {
    if constexpr (HasHint<ShapeA>) a.hint = p.ha;
    if constexpr (HasHint<ShapeB>) b.hint = p.hb;
    (void)p;
  };
  GjkEpaInfo local;
  GjkEpaInfo& inf = info ? *info : local;
  inf = GjkEpaInfo{};

  Vec3 d0 = dir;
  if (!d0.allFinite() || !(d0.squaredNorm() > 1e-300)) {
    d0 = b.center() - a.center();
    if (!d0.allFinite() || !(d0.squaredNorm() > 1e-300)) d0 = Vec3::UnitX();
  }
  constexpr bool kNamed = HasPoints<ShapeA> && HasPoints<ShapeB>;
  if (!kNamed) simplex = nullptr;
  Simplex s;
  s.p[0] = support(d0);
  s.lambda[0] = 1;
  s.n = 1;
  // Every support evaluation bounds the penetration depth from above:
  // depth <= h_C(u) = dot(u, s_C(u)) for any unit u. Keep the best one (with a
  // warm start from last step's normal it is usually already tight).
  double best_upper = std::numeric_limits<double>::infinity();
  Vec3 best_dir = Vec3::UnitZ();
  SupportPoint best_sp = s.p[0];
  const auto bound = [&](const Vec3& u, const SupportPoint& p) {
    const double h = u.dot(p.w);
    if (h < best_upper) best_upper = h, best_dir = u, best_sp = p;
  };
  bound(d0.normalized(), s.p[0]);
  double scale = (s.p[0].a - a.center()).norm() + (s.p[0].b - b.center()).norm();
  if (!(scale > 0) || !std::isfinite(scale)) scale = 1;
  const double touch = kTouchRelTol * scale;

  // --- GJK ---
  Vec3 v = s.p[0].w;
  bool overlap = false;
  if constexpr (kNamed) {
    // Restart from the kept simplex when it is nearer the origin than the
    // support point along dir (it nearly always is: the same feature).
    if (simplex && simplex->n > 0) {
      Simplex k;
      for (int i = 0; i < simplex->n && i < 3; ++i) {
        SupportPoint p;
        p.ha = simplex->a[i], p.hb = simplex->b[i];
        p.a = a.point(p.ha), p.b = b.point(p.hb);
        p.w = p.a - p.b;
        bool duplicate = false;
        for (int j = 0; j < k.n; ++j) duplicate |= (k.p[j].w == p.w);
        if (!duplicate) k.p[k.n++] = p;
      }
      Vec3 vk;
      reduce_simplex(k, vk);
      if (vk.squaredNorm() < v.squaredNorm()) s = k, v = vk;
    }
  }
  for (;;) {
    if (inf.gjk_iterations++ >= kMaxGjkIterations) break;
    const double vv = v.squaredNorm();
    if (!(vv > touch * touch)) {
      overlap = true;
      break;
    }
    const SupportPoint p = support(-v);
    bound(-v / std::sqrt(vv), p);
    if (vv - v.dot(p.w) <= kGjkRelTol * scale * std::sqrt(vv)) break;  // bounds agree
    bool duplicate = false;
    for (int i = 0; i < s.n; ++i) duplicate |= (s.p[i].w == p.w);
    if (duplicate) break;
    const Simplex before = s;
    s.p[s.n++] = p;
    Vec3 vn;
    if (reduce_simplex(s, vn)) {
      overlap = true;
      break;
    }
    if (!(vn.squaredNorm() < vv)) {  // no progress: rounding floor reached
      s = before;
      break;
    }
    v = vn;
  }

  ContactResult r;
  if (!overlap) {
    Vec3 pa = Vec3::Zero(), pb = Vec3::Zero();
    for (int i = 0; i < s.n; ++i) {
      pa += s.lambda[i] * s.p[i].a;
      pb += s.lambda[i] * s.p[i].b;
    }
    const double dist = v.norm();
    r.touching = false;
    r.depth = -dist;
    r.normal = -v / dist;
    r.point = 0.5 * (pa + pb);
    dir = r.normal;
    if constexpr (kNamed) {
      if (simplex) {
        simplex->n = std::min(s.n, 3);
        for (int i = 0; i < simplex->n; ++i) simplex->a[i] = s.p[i].ha, simplex->b[i] = s.p[i].hb;
      }
    }
    inf.simplex_size = s.n;
    for (int i = 0; i < s.n; ++i) inf.simplex[i] = s.p[i].w;
    return r;
  }

  // --- EPA: complete the simplex to a tetrahedron that holds the origin ---
  inf.used_epa = true;
  if (simplex) simplex->n = 0;
  SupportPoint t[4];
  int n = s.n;
  for (int i = 0; i < n; ++i) t[i] = s.p[i];
  const double min_gap = 1e-9 * scale;
  if (n == 1) {
    static const Vec3 kAxes[6] = {Vec3::UnitX(), -Vec3::UnitX(), Vec3::UnitY(),
                                  -Vec3::UnitY(), Vec3::UnitZ(), -Vec3::UnitZ()};
    for (const Vec3& ax : kAxes) {
      const SupportPoint p = support(ax);
      bound(ax, p);
      if ((p.w - t[0].w).norm() > min_gap) {
        t[n++] = p;
        break;
      }
    }
  }
  if (n == 2) {
    const Vec3 u = (t[1].w - t[0].w).normalized();
    int k = 0;
    u.cwiseAbs().minCoeff(&k);
    const Vec3 p1 = u.cross(Vec3::Unit(k)).normalized();
    const Vec3 p2 = u.cross(p1);
    const Vec3 tries[4] = {p1, -p1, p2, -p2};
    double best = min_gap;
    for (const Vec3& d : tries) {
      const SupportPoint p = support(d);
      bound(d, p);
      const Vec3 q = p.w - t[0].w;
      const double off = (q - q.dot(u) * u).norm();
      if (off > best) {
        best = off;
        t[2] = p;
        n = 3;
      }
    }
  }
  if (n == 3) {
    const Vec3 m = (t[1].w - t[0].w).cross(t[2].w - t[0].w).normalized();
    const SupportPoint pp = support(m), pm = support(-m);
    bound(m, pp);
    bound(-m, pm);
    const double hp = std::abs(m.dot(pp.w - t[0].w)), hm = std::abs(m.dot(pm.w - t[0].w));
    if (std::max(hp, hm) > min_gap) {
      t[3] = hp >= hm ? pp : pm;
      n = 4;
    }
  }
  if (n < 4) {  // C is flat: the shapes only touch
    r.touching = false;
    r.depth = 0;
    r.normal = d0.normalized();
    r.point = 0.5 * (t[0].a + t[0].b);
    dir = r.normal;
    return r;
  }

  Epa epa;
  const Epa::Result e = epa.run(support, seed, t, kEpaRelTol * scale);
  inf.epa_iterations = e.iterations;
  inf.epa_converged = e.converged;
  if (!e.valid || (!e.converged && best_upper < e.depth)) {
    // EPA could not certify a better bound than one met on the way: use that
    // direction, with the deepest points of A and B along it as witnesses.
    r.depth = best_upper;
    r.touching = r.depth > 0;
    r.normal = best_dir;
    r.point = 0.5 * (best_sp.a + best_sp.b);
    dir = r.normal;
    return r;
  }
  r.depth = e.depth;
  r.touching = e.depth > 0;
  r.normal = e.normal;
  r.point = 0.5 * (e.pa + e.pb);
  dir = r.normal;
  return r;
}

}  // namespace grainlab
