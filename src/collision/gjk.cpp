// GJK simplex solver, EPA polytope bookkeeping, and the collide_convex entry
// points (instantiations of gjk_epa for the shape pairs the dispatch uses).
#include "collision/gjk.h"

#include "collision/narrowphase.h"
#include "collision/penetration.h"

#include <algorithm>
#include <limits>

namespace grainlab {
namespace gjk_detail {

namespace {

// Closest point of segment (a, b) to the origin, weights in l[2].
Vec3 closest_on_segment(const Vec3& a, const Vec3& b, double l[2]) {
  const Vec3 ab = b - a;
  const double t = -a.dot(ab), den = ab.squaredNorm();
  if (t <= 0) {
    l[0] = 1, l[1] = 0;
    return a;
  }
  if (t >= den) {
    l[0] = 0, l[1] = 1;
    return b;
  }
  const double u = t / den;
  l[0] = 1 - u, l[1] = u;
  return a + u * ab;
}

}  // namespace

// Voronoi-region walk (vertex, edge, interior regions of the triangle), as in
// Ericson, Real-Time Collision Detection, section 5.1.5, with the query point
// at the origin. A degenerate (flat) triangle falls back to its three edges.
Vec3 closest_on_triangle(const Vec3& a, const Vec3& b, const Vec3& c, double l[3]) {
  const Vec3 ab = b - a, ac = c - a;
  const double d1 = -ab.dot(a), d2 = -ac.dot(a);
  if (d1 <= 0 && d2 <= 0) {
    l[0] = 1, l[1] = 0, l[2] = 0;
    return a;
  }
  const double d3 = -ab.dot(b), d4 = -ac.dot(b);
  if (d3 >= 0 && d4 <= d3) {
    l[0] = 0, l[1] = 1, l[2] = 0;
    return b;
  }
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    const double t = d1 / (d1 - d3);
    l[0] = 1 - t, l[1] = t, l[2] = 0;
    return a + t * ab;
  }
  const double d5 = -ab.dot(c), d6 = -ac.dot(c);
  if (d6 >= 0 && d5 <= d6) {
    l[0] = 0, l[1] = 0, l[2] = 1;
    return c;
  }
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    const double t = d2 / (d2 - d6);
    l[0] = 1 - t, l[1] = 0, l[2] = t;
    return a + t * ac;
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    const double t = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    l[0] = 0, l[1] = 1 - t, l[2] = t;
    return b + t * (c - b);
  }
  const double den = va + vb + vc;  // = |ab x ac|^2
  if (!(den > 1e-24 * ab.squaredNorm() * ac.squaredNorm())) {
    double ls[3][2];
    const Vec3 p[3] = {closest_on_segment(a, b, ls[0]), closest_on_segment(a, c, ls[1]),
                       closest_on_segment(b, c, ls[2])};
    int k = 0;
    for (int i = 1; i < 3; ++i)
      if (p[i].squaredNorm() < p[k].squaredNorm()) k = i;
    if (k == 0) l[0] = ls[0][0], l[1] = ls[0][1], l[2] = 0;
    if (k == 1) l[0] = ls[1][0], l[1] = 0, l[2] = ls[1][1];
    if (k == 2) l[0] = 0, l[1] = ls[2][0], l[2] = ls[2][1];
    return p[k];
  }
  const double v = vb / den, w = vc / den;
  l[0] = 1 - v - w, l[1] = v, l[2] = w;
  return a + v * ab + w * ac;
}

bool reduce_simplex(Simplex& s, Vec3& v) {
  double l[4] = {0, 0, 0, 0};
  bool inside = false;
  switch (s.n) {
    case 1:
      l[0] = 1;
      v = s.p[0].w;
      break;
    case 2:
      v = closest_on_segment(s.p[0].w, s.p[1].w, l);
      break;
    case 3:
      v = closest_on_triangle(s.p[0].w, s.p[1].w, s.p[2].w, l);
      break;
    default: {
      const Vec3 &a = s.p[0].w, &b = s.p[1].w, &c = s.p[2].w, &d = s.p[3].w;
      const double vol = (b - a).dot((c - a).cross(d - a));
      const double size = (b - a).norm() * (c - a).norm() * (d - a).norm();
      const bool solid = std::abs(vol) > 1e-12 * size;
      // Faces as index triples with the opposite vertex last. For a solid
      // tetrahedron, n = (q1 - q0) x (q2 - q0) satisfies dot(n, opp - q0) = vol,
      // so the origin is outside the face when dot(n, q0) * vol > 0.
      static constexpr int kFaces[4][3] = {{0, 1, 2}, {0, 2, 3}, {0, 3, 1}, {1, 3, 2}};
      double best = std::numeric_limits<double>::infinity();
      bool any_outside = false;
      for (const auto& f : kFaces) {
        const Vec3 &q0 = s.p[f[0]].w, &q1 = s.p[f[1]].w, &q2 = s.p[f[2]].w;
        if (solid) {
          const Vec3 nf = (q1 - q0).cross(q2 - q0);
          if (!(nf.dot(q0) * vol > 0)) continue;
        }
        any_outside = true;
        double lf[3];
        const Vec3 p = closest_on_triangle(q0, q1, q2, lf);
        const double dd = p.squaredNorm();
        if (dd < best) {
          best = dd;
          v = p;
          l[0] = l[1] = l[2] = l[3] = 0;
          l[f[0]] = lf[0], l[f[1]] = lf[1], l[f[2]] = lf[2];
        }
      }
      if (!any_outside) {
        inside = true;
        v = Vec3::Zero();
        for (int i = 0; i < 4; ++i) s.lambda[i] = 0.25;
        return true;
      }
      break;
    }
  }
  // Keep the points that carry v.
  int m = 0;
  for (int i = 0; i < s.n; ++i) {
    if (l[i] > 0) {
      s.p[m] = s.p[i];
      s.lambda[m] = l[i];
      ++m;
    }
  }
  if (m == 0) {  // cannot happen with finite input; keep the newest point
    s.p[0] = s.p[s.n - 1];
    s.lambda[0] = 1;
    m = 1;
    v = s.p[0].w;
  }
  s.n = m;
  return inside;
}

bool Epa::make_face(int f, int a, int b, int c) {
  const Vec3 &wa = verts_[a].w, &wb = verts_[b].w, &wc = verts_[c].w;
  const Vec3 e1 = wb - wa, e2 = wc - wa;
  const Vec3 n = e1.cross(e2);
  const double len = n.norm();
  if (!(len > 1e-13 * e1.norm() * e2.norm())) return false;  // sliver: give up
  Face& F = faces_[f];
  F.v[0] = a, F.v[1] = b, F.v[2] = c;
  F.n = n / len;
  F.dist = F.n.dot(wa + wb + wc) / 3;
  F.alive = true;
  return true;
}

int Epa::new_face_slot() {
  if (nfree_ > 0) return free_[--nfree_];
  if (nf_ < kMaxFaces) return nf_++;
  return -1;
}

void Epa::record(int f, double upper, Result& r) const {
  const Face& F = faces_[f];
  double l[3];
  closest_on_triangle(verts_[F.v[0]].w, verts_[F.v[1]].w, verts_[F.v[2]].w, l);
  r.pa = l[0] * verts_[F.v[0]].a + l[1] * verts_[F.v[1]].a + l[2] * verts_[F.v[2]].a;
  r.pb = l[0] * verts_[F.v[0]].b + l[1] * verts_[F.v[1]].b + l[2] * verts_[F.v[2]].b;
  r.depth = upper;
  r.normal = F.n;
  r.valid = true;
}

// Removes the faces seen from vertex wi (a connected region grown from the
// closest face over the adjacency) and closes the hole with a fan to wi.
bool Epa::expand(int closest, int wi) {
  struct Edge {
    int face, edge;
  };
  Edge stack[3 * kMaxFaces];
  Edge horizon[kMaxFaces];
  int ns = 0, nh = 0;
  const Vec3& w = verts_[wi].w;
  const auto visible = [&](const Face& F) { return F.n.dot(w - verts_[F.v[0]].w) > 0; };

  faces_[closest].alive = false;
  free_[nfree_++] = closest;
  for (int e = 2; e >= 0; --e)
    stack[ns++] = {faces_[closest].adj[e], faces_[closest].adj_edge[e]};
  while (ns > 0) {
    const Edge it = stack[--ns];
    Face& F = faces_[it.face];
    if (!F.alive) continue;
    if (visible(F)) {
      F.alive = false;
      free_[nfree_++] = it.face;
      if (ns + 2 > 3 * kMaxFaces) return false;
      stack[ns++] = {F.adj[(it.edge + 2) % 3], F.adj_edge[(it.edge + 2) % 3]};
      stack[ns++] = {F.adj[(it.edge + 1) % 3], F.adj_edge[(it.edge + 1) % 3]};
    } else {
      if (nh == kMaxFaces) return false;
      horizon[nh++] = it;
    }
  }
  if (nh < 3 || nh > nfree_ + (kMaxFaces - nf_)) return false;

  // One new face (a, b, wi) per horizon edge; a faces' "a" vertex is unique
  // around the fan, which links the new faces to each other.
  int by_a[kMaxVertices];
  for (int i = 0; i < nv_; ++i) by_a[i] = -1;
  int created[kMaxFaces];
  for (int k = 0; k < nh; ++k) {
    const Face& H = faces_[horizon[k].face];
    const int e = horizon[k].edge;
    const int a = H.v[(e + 1) % 3], b = H.v[e];
    const int f = new_face_slot();
    if (f < 0 || !make_face(f, a, b, wi)) return false;
    faces_[f].adj[0] = horizon[k].face;
    faces_[f].adj_edge[0] = e;
    faces_[horizon[k].face].adj[e] = f;
    faces_[horizon[k].face].adj_edge[e] = 0;
    if (by_a[a] >= 0) return false;  // horizon is not a simple loop
    by_a[a] = f;
    created[k] = f;
  }
  for (int k = 0; k < nh; ++k) {
    Face& F = faces_[created[k]];
    const int g = by_a[F.v[1]];
    if (g < 0) return false;
    F.adj[1] = g;
    F.adj_edge[1] = 2;
    faces_[g].adj[2] = created[k];
    faces_[g].adj_edge[2] = 1;
  }
  return true;
}

}  // namespace gjk_detail

// Polytope pairs take the translated-GJK path (penetration.h) when `dir` is
// warm (last step's normal of this pair) and it concludes; GJK/EPA otherwise.
ContactResult collide_convex(const PolytopeShape& a, const PolytopeShape& b, Vec3& dir, bool warm,
                             SimplexCache* simplex) {
  ContactResult r;
  if (!(warm && warm_penetration(a, b, dir, r, simplex))) r = gjk_epa(a, b, dir, nullptr, simplex);
  contact_patch(a, b, r);
  return r;
}
// A box wall against a grain: GJK/EPA (or the warm path) for depth and
// normal. When the normal is one of the box's face normals (a grain pressed on
// a face of the slab, the usual case), the contact is the exact plane
// routine's for that face (its soft depth, a conservative force, so a flat
// grain face resting on the slab neither jitters nor gains energy). Edge and
// corner contacts keep the witness point.
ContactResult collide_convex(const BoxShape& a, const PolytopeShape& b, Vec3& dir, bool warm) {
  ContactResult r;
  if (!(warm && warm_penetration(a, b, dir, r))) r = gjk_epa(a, b, dir);
  if (!r.touching) return r;
  for (int axis = 0; axis < 3; ++axis) {
    const double c = r.normal.dot(a.rot.col(axis));
    if (std::abs(c) < 1 - 1e-9) continue;
    const Vec3 n = (c > 0 ? 1.0 : -1.0) * a.rot.col(axis);
    const ContactResult face = collide(PlaneShape{a.pos + a.half[axis] * n, n}, b);
    if (face.touching) r = face;  // the plane's soft depth (soft_depth.h)
    break;
  }
  return r;
}
ContactResult collide_convex(const BoxShape& a, const SphereShape& b, Vec3& dir) {
  return gjk_epa(a, b, dir);
}

}  // namespace grainlab
