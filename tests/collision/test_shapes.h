// Test helpers: random convex polytopes with their vertex adjacency, built
// without qhull by a small incremental hull, and brute-force references.
#pragma once

#include "collision/posed_shape.h"
#include "collision/shapes.h"
#include "core/rng.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <stdexcept>
#include <utility>
#include <vector>

namespace grainlab::testing {

// A hull: vertices (all extreme), outward triangles, and the polytope built on them.
struct TestHull {
  std::vector<Vec3> vertices;
  std::vector<std::array<int, 3>> faces;
  ConvexPolytope poly;
};

inline Vec3 tri_normal(const Vec3& a, const Vec3& b, const Vec3& c) {
  return (b - a).cross(c - a);
}

// Incremental 3D convex hull, O(n * faces): fine for test sizes (<= ~1500).
// Points are assumed in general position (random input).
inline TestHull convex_hull(const std::vector<Vec3>& pts) {
  const int n = static_cast<int>(pts.size());
  if (n < 4) throw std::runtime_error("convex_hull: need 4 points");
  double scale = 0;
  for (const Vec3& p : pts) scale = std::max(scale, p.norm());
  const double eps = 1e-12 * scale;
  // Initial tetrahedron: 0, farthest from 0, farthest from that line, farthest from that plane.
  int i0 = 0, i1 = 0, i2 = 0, i3 = 0;
  for (int i = 0; i < n; ++i)
    if ((pts[i] - pts[i0]).norm() > (pts[i1] - pts[i0]).norm()) i1 = i;
  const Vec3 u = (pts[i1] - pts[i0]).normalized();
  double best = -1;
  for (int i = 0; i < n; ++i) {
    const Vec3 q = pts[i] - pts[i0];
    const double d = (q - q.dot(u) * u).norm();
    if (d > best) best = d, i2 = i;
  }
  const Vec3 m = tri_normal(pts[i0], pts[i1], pts[i2]).normalized();
  best = -1;
  for (int i = 0; i < n; ++i) {
    const double d = std::abs(m.dot(pts[i] - pts[i0]));
    if (d > best) best = d, i3 = i;
  }
  struct F {
    int v[3];
    Vec3 n;
    double d;
    bool alive;
  };
  std::vector<F> faces;
  const auto add = [&](int a, int b, int c) {
    F f{{a, b, c}, tri_normal(pts[a], pts[b], pts[c]).normalized(), 0, true};
    f.d = f.n.dot(pts[a]);
    faces.push_back(f);
  };
  const Vec3 centroid = 0.25 * (pts[i0] + pts[i1] + pts[i2] + pts[i3]);
  const int tet[4][3] = {{i0, i1, i2}, {i0, i1, i3}, {i0, i2, i3}, {i1, i2, i3}};
  for (const auto& t : tet) {
    if (tri_normal(pts[t[0]], pts[t[1]], pts[t[2]]).dot(pts[t[0]] - centroid) > 0)
      add(t[0], t[1], t[2]);
    else
      add(t[0], t[2], t[1]);
  }
  for (int i = 0; i < n; ++i) {
    if (i == i0 || i == i1 || i == i2 || i == i3) continue;
    std::map<std::pair<int, int>, int> edges;
    bool any = false;
    for (F& f : faces) {
      if (!f.alive || f.n.dot(pts[i]) - f.d <= eps) continue;
      any = true;
      f.alive = false;
      for (int e = 0; e < 3; ++e) edges[{f.v[e], f.v[(e + 1) % 3]}] = 1;
    }
    if (!any) continue;
    for (const auto& [e, one] : edges)
      if (!edges.count({e.second, e.first})) add(e.first, e.second, i);
    std::erase_if(faces, [](const F& f) { return !f.alive; });
  }
  // Keep the vertices the hull uses, renumbered.
  std::vector<int> id(n, -1);
  TestHull h;
  for (const F& f : faces)
    for (int k : f.v)
      if (id[k] < 0) id[k] = static_cast<int>(h.vertices.size()), h.vertices.push_back(pts[k]);
  std::vector<std::vector<Index>> nb(h.vertices.size());
  for (const F& f : faces) {
    h.faces.push_back({id[f.v[0]], id[f.v[1]], id[f.v[2]]});
    for (int e = 0; e < 3; ++e) nb[id[f.v[e]]].push_back(id[f.v[(e + 1) % 3]]);
  }
  std::vector<Index> offsets{0}, adj;
  for (auto& l : nb) {
    std::sort(l.begin(), l.end());
    l.erase(std::unique(l.begin(), l.end()), l.end());
    adj.insert(adj.end(), l.begin(), l.end());
    offsets.push_back(static_cast<Index>(adj.size()));
  }
  h.poly = ConvexPolytope(h.vertices, offsets, adj);
  return h;
}

// Applies a linear map to a hull: a linear image of a convex polytope is convex
// with the same faces and vertex graph.
inline TestHull mapped(const TestHull& h, const Mat3& L) {
  std::vector<Vec3> pts;
  for (const Vec3& v : h.vertices) pts.push_back(L * v);
  TestHull out;
  out.vertices = pts;
  out.faces = h.faces;
  std::vector<Index> offsets{0}, adj;
  for (std::size_t v = 0; v < h.poly.size(); ++v) {
    for (auto it = h.poly.neighbours_begin(static_cast<Index>(v));
         it != h.poly.neighbours_end(static_cast<Index>(v)); ++it)
      adj.push_back(*it);
    offsets.push_back(static_cast<Index>(adj.size()));
  }
  if (L.determinant() < 0)  // a reflection flips the face orientation
    for (auto& f : out.faces) std::swap(f[1], f[2]);
  out.poly = ConvexPolytope(pts, offsets, adj);
  return out;
}

// Random well-conditioned linear map: rotation * diag(s) * rotation, s in [lo, hi].
inline Mat3 random_linear(Rng& rng, double lo, double hi) {
  const Vec3 s(rng.uniform(lo, hi), rng.uniform(lo, hi), rng.uniform(lo, hi));
  return rng.rotation().toRotationMatrix() * s.asDiagonal() * rng.rotation().toRotationMatrix();
}

// n points on the unit sphere, hulled, then stretched into an ellipsoid with
// semi-axes in [lo, hi]: all points stay vertices.
inline TestHull random_ellipsoid_hull(Rng& rng, int n, double lo = 0.5, double hi = 1.5) {
  std::vector<Vec3> pts;
  for (int i = 0; i < n; ++i) pts.push_back(rng.unit_vector());
  return mapped(convex_hull(pts), random_linear(rng, lo, hi));
}

// An irregular "grain": hull of n points with radius in [0.8, 1] (the interior
// ones drop out), stretched by a random linear map.
inline TestHull random_blob_hull(Rng& rng, int n, double lo = 0.6, double hi = 1.2) {
  std::vector<Vec3> pts;
  for (int i = 0; i < n; ++i) pts.push_back(rng.uniform(0.8, 1.0) * rng.unit_vector());
  return mapped(convex_hull(pts), random_linear(rng, lo, hi));
}

// Box with half extents `half` (8 vertices, 3 neighbours each), 12 triangles.
inline TestHull box_hull(const Vec3& half) {
  std::vector<Vec3> pts;
  for (int i = 0; i < 8; ++i)
    pts.emplace_back((i & 1) ? half.x() : -half.x(), (i & 2) ? half.y() : -half.y(),
                     (i & 4) ? half.z() : -half.z());
  TestHull h;
  h.vertices = pts;
  std::vector<Index> offsets{0}, adj;
  for (int i = 0; i < 8; ++i) {
    for (int bit : {1, 2, 4}) adj.push_back(i ^ bit);
    offsets.push_back(static_cast<Index>(adj.size()));
  }
  // Faces: for each axis and side, two triangles, oriented outward.
  for (int ax = 0; ax < 3; ++ax)
    for (int side = 0; side < 2; ++side) {
      std::vector<int> q;
      for (int i = 0; i < 8; ++i)
        if (((i >> ax) & 1) == side) q.push_back(i);
      // q in bit order forms a 2x2 grid: 0 1 / 2 3 -> quad 0,1,3,2
      const int quad[4] = {q[0], q[1], q[3], q[2]};
      Vec3 out = Vec3::Zero();
      out[ax] = side ? 1 : -1;
      std::array<int, 3> t1{quad[0], quad[1], quad[2]}, t2{quad[0], quad[2], quad[3]};
      if (tri_normal(pts[t1[0]], pts[t1[1]], pts[t1[2]]).dot(out) < 0) {
        std::swap(t1[1], t1[2]);
        std::swap(t2[1], t2[2]);
      }
      h.faces.push_back(t1);
      h.faces.push_back(t2);
    }
  h.poly = ConvexPolytope(pts, offsets, adj);
  return h;
}

// A hull placed for the shape-pair table (the rotation is kept by reference).
inline PosedShape posed_polytope(const ConvexPolytope& hull, const Mat3& rot, const Quat& q, const Vec3& pos,
                                 double scale) {
  PosedShape p;
  p.kind = ShapeKind::Polytope;
  p.geometry = &hull;
  p.rot = &rot;
  p.q = &q;
  p.pos = pos;
  p.scale = scale;
  return p;
}

// World-space vertices of a placed polytope.
inline std::vector<Vec3> world_vertices(const PolytopeShape& s) {
  std::vector<Vec3> out;
  for (const Vec3& v : s.poly->vertices()) out.push_back(s.pos + s.scale * (s.rot * v));
  return out;
}

// Brute-force support value max_v dot(v, d).
inline double support_value(const std::vector<Vec3>& pts, const Vec3& d) {
  double best = -1e300;
  for (const Vec3& p : pts) best = std::max(best, p.dot(d));
  return best;
}

// Two random blob hulls of size ~1 mm near x = 1 cm, B moved so that the
// support overlap along the random unit u is `delta` (negative: apart by at
// least -delta). The shapes point into `ha`, `hb`: keep the pair in place.
struct BlobPair {
  TestHull ha, hb;
  PolytopeShape a, b;
};
inline BlobPair make_blob_pair(Rng& rng, int nverts, double delta, Vec3& u) {
  BlobPair p;
  const double L = 1e-3;
  p.ha = random_blob_hull(rng, nverts);
  p.hb = random_blob_hull(rng, nverts);
  p.a = PolytopeShape{&p.ha.poly, rng.rotation().toRotationMatrix(), Vec3(1e-2, 0, 0), L, 0};
  p.b = PolytopeShape{&p.hb.poly, rng.rotation().toRotationMatrix(), Vec3::Zero(), L, 0};
  u = rng.unit_vector();
  const auto overlap = [&](const Vec3& n) { return n.dot(p.a.support(n) - p.b.support(-n)); };
  p.b.pos = p.a.pos;  // then h_C(u) = overlap(u): move B out along u to leave `delta`
  p.b.pos = p.a.pos + (overlap(u) - delta) * u;
  return p;
}

}  // namespace grainlab::testing
