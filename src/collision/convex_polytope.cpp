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
