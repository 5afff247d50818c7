// Warm-started penetration depth by translated GJK: the fast path for DEM
// contacts, whose overlaps are tiny and whose normal changes little per step.
//
// The penetration depth of A and B is PD = min over unit u of h_C(u), with
// C = A - B and h_C(u) = h_A(u) + h_B(-u) the support overlap along u (every
// u gives an upper bound: moving B by h_C(u) u separates the shapes).
// Given last step's normal n, translate B out along n by slightly more than
// h_C(n): the shapes are then separated, and GJK gives their distance s,
// closest points p_A, p_B' and normal n'. For C convex, if n is the optimal
// direction the closest point of the translated C to the origin is exactly
// the point where the origin's ray leaves C, so n' = n and p_A, p_B = p_B' - t
// are the deepest points (the witness points EPA would give). If n is slightly
// off, n' is the normal at a nearby boundary point: iterate n <- n' (a fixed
// point iteration on the boundary of C, exact once the optimal face of a
// polytope is found, usually in one or two steps). The smallest h_C(u) seen
// is returned with its direction, so the result has EPA's semantics
// (`gjk.h`), and every GJK call here is the cheap separated case.
//
// The iteration is local: from a poor starting direction it can settle on a
// locally optimal face. Callers use it only with a warm direction (the pair's
// normal from the previous step, separated or touching); it reports failure
// (the caller falls back to GJK/EPA) if the shapes are apart along a later
// direction, if the depth found exceeds 5 % of the shapes' size, or if the
// iteration does not settle and GJK finds the shapes apart.
//
// Shortcuts keep it cheap. Shapes clearly apart along the warm direction
// (h_C(n) < -1 % of their size) are reported apart with depth h_C(n), minus a
// lower bound of the gap, without GJK. The iteration stops once a step
// improves the depth by less than 1e-6 of itself (the force changes by under
// 2e-6 of itself). And it stops without the confirming GJK when the first one
// proves the fixed point: its closest point lies on a face triangle of C that
// also holds the origin's foot (see the loop). Cheapest of all, with the
// pair's kept simplex (simplex_cache.h) that proof is made before any GJK,
// from the triangle the last call ended on (kept_face): one support query on
// each shape, on the settled 2000-face bed for nearly every touching pair.
#pragma once

#include "collision/gjk.h"
#include "collision/shapes.h"

#include <limits>

namespace grainlab {

namespace penetration_detail {
// Whether q, a point on the plane of triangle t[0..2], lies inside it.
// On success also its barycentric weights l (q = l0 t0 + l1 t1 + l2 t2).
inline bool inside_triangle(const Vec3 t[3], const Vec3& q, double* l = nullptr) {
  const Vec3 e0 = t[1] - t[0], e1 = t[2] - t[0], r = q - t[0];
  const double d00 = e0.dot(e0), d01 = e0.dot(e1), d11 = e1.dot(e1);
  const double d20 = r.dot(e0), d21 = r.dot(e1);
  const double den = d00 * d11 - d01 * d01;
  if (!(den > 0)) return false;
  const double v = (d11 * d20 - d01 * d21) / den, w = (d00 * d21 - d01 * d20) / den;
  if (!(v >= 0 && w >= 0 && v + w <= 1)) return false;
  if (l) l[0] = 1 - v - w, l[1] = v, l[2] = w;
  return true;
}

// The fixed point of warm_penetration below, proved from the pair's kept
// simplex without GJK. If the kept triangle W = {A[i_k] - B[j_k]} spans a
// plane (unit normal n away from the origin, offset h > 0) that supports
// C = A - B (h_C(n) = h: one hill climb on each shape, started at the
// triangle's vertices) and holds the origin's foot h n inside W, then the
// translated GJK along n would return W's face again: the point of C nearest
// the shifted origin is the foot, on W. The answer is then that of the loop
// below: depth h_C(n), normal n, witness points A's and B's parts of the foot.
template <class ShapeA>
bool kept_face(const ShapeA& a, const PolytopeShape& b, const SimplexCache& k, Vec3& dir, ContactResult& out) {
  if constexpr (!gjk_detail::HasPoints<ShapeA>) {
    return false;
  } else {
    if (k.n != 3) return false;
    Vec3 pa[3], pb[3], w[3];
    for (int i = 0; i < 3; ++i) pa[i] = a.point(k.a[i]), pb[i] = b.point(k.b[i]), w[i] = pa[i] - pb[i];
    Vec3 n = (w[1] - w[0]).cross(w[2] - w[0]);
    const double len = n.norm();
    if (!(len > 0) || !std::isfinite(len)) return false;
    // Oriented as the pair's last normal (from A to B), W's plane must have
    // the origin behind it: if not, the pair was apart (the triangle faces
    // the origin from outside C) and GJK has to say how far.
    n *= (n.dot(dir) < 0 ? -1 : 1) / len;
    const double h = n.dot(w[0]);
    if (!(h > 0)) return false;
    double l[3];
    if (!inside_triangle(w, h * n, l)) return false;
    const Index hint_a = a.hint, hint_b = b.hint;
    a.hint = k.a[0], b.hint = k.b[0];
    const Vec3 sa = a.support(n), sb = b.support(-n);
    const double hc = n.dot(sa - sb);
    const double size = (sa - a.center()).norm() + (sb - b.center()).norm();
    if (!(hc - h <= gjk_detail::kGjkRelTol * size) || !(hc <= 0.05 * size)) {
      a.hint = hint_a, b.hint = hint_b;
      return false;
    }
    out = ContactResult{};
    out.touching = true;
    out.depth = hc;
    out.normal = n;
    out.point = 0.5 * (l[0] * (pa[0] + pb[0]) + l[1] * (pa[1] + pb[1]) + l[2] * (pa[2] + pb[2]));
    dir = n;
    return true;
  }
}
}  // namespace penetration_detail

// A PolytopeShape moved by t, sharing the original's hill-climbing hint.
struct ShiftedPolytope {
  const PolytopeShape& shape;
  Vec3 t;
  Index& hint;
  Vec3 support(const Vec3& d) const {
    shape.hint = hint;
    const Vec3 p = shape.support(d) + t;
    hint = shape.hint;
    return p;
  }
  Vec3 point(Index i) const { return shape.point(i) + t; }
  Vec3 center() const { return shape.center() + t; }
};

// Penetration of A and polytope B by translated GJK, starting from `dir` (from A
// to B). Returns false, leaving `out` unset, if A and B do not overlap along
// dir or the iteration cannot conclude; the caller then runs gjk_epa.
// `simplex` (optional) carries each GJK's final simplex to the next
// (simplex_cache.h): one pair's GJKs here and in later steps start there.
template <class ShapeA>
bool warm_penetration(const ShapeA& a, const PolytopeShape& b, Vec3& dir, ContactResult& out,
                      SimplexCache* simplex = nullptr) {
  if (simplex && penetration_detail::kept_face(a, b, *simplex, dir, out)) return true;
  const double len = dir.norm();
  if (!(len > 0) || !std::isfinite(len)) return false;
  Vec3 n = dir / len;
  Vec3 sa = a.support(n), sb = b.support(-n);
  double h = n.dot(sa - sb);
  const double size = (sa - a.center()).norm() + (sb - b.center()).norm();
  if (!(h > 0)) {
    // Apart along dir: -h bounds the gap from below. Far apart (more than 1 %
    // of the shapes' size, hundreds of steps of relative motion) that is all
    // a step needs; nearer, GJK measures the gap and refreshes dir, so the
    // contact to come starts from the exact closest direction.
    if (!(h < -1e-2 * size)) return false;
    if (simplex) simplex->n = 0;  // no GJK ran: the kept simplex is stale
    out = ContactResult{};
    out.depth = h;
    out.normal = n;
    return true;
  }
  double best = std::numeric_limits<double>::infinity();
  Vec3 best_n = n, best_point = Vec3::Zero();
  bool settled = false;
  for (int iter = 0; iter < 6; ++iter) {
    const Vec3 t = (h + 1e-3 * h + 1e-9 * size) * n;
    const ShiftedPolytope moved{b, t, b.hint};
    Vec3 d = n;
    GjkEpaInfo info;
    const ContactResult g = gjk_epa(a, moved, d, &info, simplex);
    if (g.touching) return false;  // rounding: let EPA decide
    const Vec3 n2 = g.normal;
    const double h2 = n2.dot(a.support(n2) - b.support(-n2));
    if (h2 < best) {  // witness points: p_A and p_B' - t
      best = h2;
      best_n = n2;
      best_point = g.point - 0.5 * t;
    }
    if (!(h2 > 0)) return false;  // a separating direction: GJK measures the gap
    // Settled when the direction or the depth stops changing, or at a fixed
    // point proved without another GJK: the closest point lies on a triangle
    // T of a face of C (normal n2), and the origin's foot on that face, h2 n2,
    // lies inside T too (in the shifted frame: h2 n2 - t). The next iteration
    // would shift along n2, find the same face and return n2 again.
    settled = (n2 - n).squaredNorm() < 1e-20 || (h2 <= h && h - h2 < 1e-6 * h) ||
              (info.simplex_size == 3 && h2 <= h && penetration_detail::inside_triangle(info.simplex, h2 * n2 - t));
    if (settled) break;
    n = n2;
    h = h2;
  }
  // Only shallow contacts are this routine's business: a deep answer means the
  // start direction was poor (the local iteration may have found the wrong face).
  if (!std::isfinite(best) || best > 0.05 * size) return false;
  // Not settled in six steps: the smallest h_C seen bounds the depth from
  // above only if the shapes overlap at all. An iteration that wanders (from
  // a poor direction) can see only positive h_C of shapes that are apart, so
  // GJK on the pair decides (the hints restored: this call's answer stays as
  // it was); apart, GJK/EPA answers instead (about one call in 1e5 of a
  // direct shear does not settle, each of them a contact).
  if (!settled) {
    Index hint_a = 0;
    if constexpr (gjk_detail::HasHint<ShapeA>) hint_a = a.hint;
    const Index hint_b = b.hint;
    Vec3 d = n;
    const bool overlap = gjk_epa(a, b, d).touching;
    if constexpr (gjk_detail::HasHint<ShapeA>) a.hint = hint_a;
    b.hint = hint_b;
    if (!overlap) return false;
  }
  out.touching = best > 0;
  out.depth = best;
  out.normal = best_n;
  out.point = best_point;
  dir = best_n;
  return true;
}

}  // namespace grainlab
