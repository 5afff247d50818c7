// ConvexPolytope: vertex storage and support queries by hill climbing.
//
// Hill climbing is exact on a convex polytope: a linear function restricted to
// the vertex graph of a polytope has no local maximum other than the global
// one (the argument of the simplex method), so from any vertex that is not a
// maximiser some edge leads to a neighbour with a strictly larger value. The
// climb below moves to the best neighbour while the value strictly increases;
// it stops because the value increases at every move and there are finitely
// many vertices.
#include "collision/shapes.h"

#include "core/error.h"

#include <algorithm>

namespace grainlab {

ConvexPolytope::ConvexPolytope(std::vector<Vec3> vertices,
                               std::vector<Index> adjacency_offsets,
                               std::vector<Index> adjacency)
    : vertices_(std::move(vertices)),
      offsets_(std::move(adjacency_offsets)),
      adjacency_(std::move(adjacency)) {
  const std::size_t n = vertices_.size();
  if (n == 0) input_error("ConvexPolytope: no vertices; a convex shape needs at least one");
  if (offsets_.size() != n + 1)
    input_error("ConvexPolytope: {} adjacency offsets for {} vertices; expected {} (one per vertex plus one)",
                offsets_.size(), n, n + 1);
  if (offsets_.front() != 0 || static_cast<std::size_t>(offsets_.back()) != adjacency_.size())
    input_error("ConvexPolytope: adjacency offsets must start at 0 and end at the adjacency size {}",
                adjacency_.size());
  for (std::size_t v = 0; v < n; ++v) {
    if (offsets_[v + 1] < offsets_[v])
      input_error("ConvexPolytope: adjacency offsets decrease at vertex {}", v);
  }
  for (const Index a : adjacency_) {
    if (a < 0 || static_cast<std::size_t>(a) >= n)
      input_error("ConvexPolytope: neighbour index {} out of range [0, {})", a, n);
  }
  for (const Vec3& v : vertices_) {
    if (!v.allFinite()) input_error("ConvexPolytope: a vertex is not finite (NaN or infinity)");
    bounding_radius_ = std::max(bounding_radius_, v.norm());
  }
  build_planes();
  // An adjacency entry is an edge if its two vertices share two face planes
  // (all are, where no planes were found).
  is_edge_.assign(adjacency_.size(), 1);
  if (!planes_.empty())
    for (std::size_t v = 0; v < n; ++v)
      for (Index i = offsets_[v]; i < offsets_[v + 1]; ++i) {
        int shared = 0;
        for (Index p = plane_offsets_[v]; p < plane_offsets_[v + 1]; ++p)
          for (Index q = plane_offsets_[adjacency_[i]]; q < plane_offsets_[adjacency_[i] + 1]; ++q)
            shared += vertex_planes_[p] == vertex_planes_[q];
        is_edge_[i] = shared >= 2;
      }
}

// A plane through vertex u and two of its neighbours v, w is a face plane if
// it supports the polytope (no vertex beyond it): checked by a hill climb from
// u, exact on a convex polytope. Every vertex of a face finds that face from
// its two neighbours along the face boundary, so each vertex lists all its
// faces. Planes equal within rounding are stored once.
void ConvexPolytope::build_planes() {
  const Index n = static_cast<Index>(vertices_.size());
  plane_offsets_.assign(1, 0);
  if (n < 4) {
    plane_offsets_.assign(n + 1, 0);
    return;
  }
  const double tol = 1e-9 * std::max(bounding_radius_, 1e-300);
  std::vector<Index> mine;
  for (Index u = 0; u < n; ++u) {
    mine.clear();
    const Vec3& pu = vertices_[u];
    for (Index i = offsets_[u]; i < offsets_[u + 1]; ++i) {
      for (Index j = i + 1; j < offsets_[u + 1]; ++j) {
        const Vec3 e1 = vertices_[adjacency_[i]] - pu, e2 = vertices_[adjacency_[j]] - pu;
        Vec3 m = e1.cross(e2);
        const double len = m.norm();
        if (!(len > 1e-12 * e1.norm() * e2.norm())) continue;
        m /= len;
        for (int sign = 0; sign < 2; ++sign, m = -m) {
          const double c = m.dot(pu);
          const Index s = support_index(m, u);
          if (vertices_[s].dot(m) - c > tol) continue;
          bool dup = false;
          for (const Index k : mine)
            if (planes_[k].m.dot(m) > 1 - 1e-9 && std::abs(planes_[k].c - c) < 1e3 * tol) dup = true;
          if (dup) break;
          // Shared with a neighbour that found it first?
          Index found = -1;
          for (Index a = offsets_[u]; a < offsets_[u + 1] && found < 0; ++a) {
            const Index nb = adjacency_[a];
            if (nb > u) continue;
            for (Index q = plane_offsets_[nb]; q < plane_offsets_[nb + 1]; ++q) {
              const Plane& P = planes_[vertex_planes_[q]];
              if (P.m.dot(m) > 1 - 1e-9 && std::abs(P.c - c) < 1e3 * tol) {
                found = vertex_planes_[q];
                break;
              }
            }
          }
          if (found < 0) {
            found = static_cast<Index>(planes_.size());
            planes_.push_back({m, c});
          }
          mine.push_back(found);
          break;
        }
      }
    }
    vertex_planes_.insert(vertex_planes_.end(), mine.begin(), mine.end());
    plane_offsets_.push_back(static_cast<Index>(vertex_planes_.size()));
  }
}

Index ConvexPolytope::support_index(const Vec3& d, Index start) const {
  const Index n = static_cast<Index>(vertices_.size());
  Index v = (start >= 0 && start < n) ? start : 0;
  double best = vertices_[v].dot(d);
  for (;;) {
    Index next = v;
    const Index* end = adjacency_.data() + offsets_[v + 1];
    for (const Index* it = adjacency_.data() + offsets_[v]; it != end; ++it) {
      const double t = vertices_[*it].dot(d);
      if (t > best) {
        best = t;
        next = *it;
      }
    }
    if (next == v) return v;
    v = next;
  }
}

}  // namespace grainlab
