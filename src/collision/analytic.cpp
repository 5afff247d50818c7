// Closed-form narrowphase: sphere-sphere, plane-sphere, plane-polytope.
#include "collision/narrowphase.h"
#include "collision/soft_depth.h"
#include "collision/sphere_pairs.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace grainlab {

ContactResult collide(const SphereShape& a, const SphereShape& b) {
  static_assert(sizeof(SphereShape) == 4 * sizeof(double) && offsetof(SphereShape, radius) == 3 * sizeof(double),
                "a SphereShape is read as x, y, z, radius");
  const SphereXYZR pa[4] = {a.pos.data(), a.pos.data(), a.pos.data(), a.pos.data()};  // the pair in every lane
  const SphereXYZR pb[4] = {b.pos.data(), b.pos.data(), b.pos.data(), b.pos.data()};
  SpherePairsOut out;
  sphere_pairs(pa, pb, out);
  return sphere_pair_result(out, 0);
}

ContactResult collide(const PlaneShape& a, const SphereShape& b) {
  ContactResult r;
  r.normal = a.normal;
  const double s = (b.pos - a.point).dot(a.normal);  // height of the centre
  r.depth = b.radius - s;
  r.touching = r.depth > 0;
  // Midway between the sphere's lowest point (height s - radius) and the plane.
  r.point = b.pos - 0.5 * (s + b.radius) * a.normal;
  return r;
}

// Deepest vertex by a support query on -normal, then a breadth-first walk from
// it over the vertices below the plane. That set is connected in the edge graph
// (from any vertex below the plane a height-decreasing edge path reaches the
// deepest vertex), so the walk finds all of them while visiting only them and
// their neighbours. The part below the plane of each edge at those vertices
// enters the soft depth (soft_depth.h) with its depth, pushed along the plane
// normal: the force is the exact gradient of u(D), so a face rocking on the
// plane gains no energy.
ContactResult collide(const PlaneShape& a, const PolytopeShape& b) {
  ContactResult r;
  r.normal = a.normal;
  const ConvexPolytope& poly = *b.poly;
  const Vec3 nl = b.scale * (b.rot.transpose() * a.normal);  // height = h0 + dot(v_local, nl)
  const double h0 = (b.pos - a.point).dot(a.normal);
  const Index deepest = poly.support_index(-nl, b.hint);
  b.hint = deepest;
  const double hmin = h0 + poly.vertex(deepest).dot(nl);
  r.depth = -hmin;
  r.touching = r.depth > 0;
  const Vec3 pdeep = b.pos + b.scale * (b.rot * poly.vertex(deepest));
  if (!r.touching) {
    r.point = pdeep - 0.5 * hmin * a.normal;
    return r;
  }

  // Visit stamps and queue are per thread and reused: no allocation once warm.
  thread_local std::vector<std::uint32_t> stamp;
  thread_local std::vector<Index> queue;
  thread_local std::uint32_t generation = 0;
  if (stamp.size() < poly.size()) stamp.assign(poly.size(), 0);
  if (++generation == 0) {
    std::fill(stamp.begin(), stamp.end(), 0u);
    generation = 1;
  }
  queue.clear();
  queue.push_back(deepest);
  stamp[deepest] = generation;
  SoftDepth soft(b.pos);
  const auto depth_of = [&](Index v) { return -(h0 + poly.vertex(v).dot(nl)); };
  for (std::size_t q = 0; q < queue.size(); ++q) {
    const Index v = queue[q];
    const double d = depth_of(v);
    const Vec3 x = b.pos + b.scale * (b.rot * poly.vertex(v));
    for (const Index* it = poly.neighbours_begin(v); it != poly.neighbours_end(v); ++it) {
      const double dw = depth_of(*it);
      // Each edge once: from v, unless w is below the plane too and has the smaller index.
      if (poly.is_edge(it) && !(dw > 0 && *it < v))
        soft.add_linear_piece(x, b.pos + b.scale * (b.rot * poly.vertex(*it)), d, dw, a.normal);
      if (stamp[*it] == generation) continue;
      stamp[*it] = generation;
      if (dw > 0) queue.push_back(*it);
    }
  }
  if (soft.finish(r, a.normal))
    r.normal = a.normal;  // every vertex is pushed along it: G is parallel to it up to rounding
  else
    r.point = pdeep - 0.5 * hmin * a.normal;  // no edge below (a degenerate hull): the deepest vertex
  return r;
}

}  // namespace grainlab
