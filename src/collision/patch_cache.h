// What a touching pair of polytopes keeps of its contact patch between steps
// (patch.cpp): which edges of each body can reach inside the other, and for
// each of them the few face planes of the other body that can be on the
// lower envelope of its depth. A cached step walks only those edges over
// those lines, at the new poses, instead of classing every edge at the
// contact against every candidate plane, building rows of distances and
// filtering each edge's lines.
//
// Why the result is the same bits. Along an edge x(t), t in [0, 1], the depth
// inside the other body o is the lower envelope E(t) = min_k l_k(t) of the
// lines l_k(t) = c_k - m_k . x(t) (o's local frame, |m_k| = 1) over o's
// candidate planes. When the cache is filled, every line whose gap
// min_t (l_k(t) - E(t)) (taken at E's corners, where the convex l_k - E is
// lowest) is below `margin` is kept; the others lie at least `margin` above
// E on the whole edge. An edge is left out only when one plane puts both of
// its ends at least `margin` outside o. If each point of the body has since
// moved by at most delta in o's frame, each l_k(t), and so E(t), moved by at
// most delta: a line left out is still above E by margin - 2 delta, and an
// edge left out still outside. So while 2 delta + kTieSlack < margin the
// kept lines hold every line of E, each other line at least kTieSlack above
// it (its crossings far from the walk's 1e-12 ties), and the walk over them
// takes the same lines and computes the same crossings, in the same order,
// as the walk over the lines add_edges keeps: the same pieces, the same
// rounding. An edge add_edges skips (one line outside at both ends) is
// skipped when a kept line says so; when only a line left out would, that
// line is above E by the margin, E < 0 at every corner and the walk adds
// nothing either. delta is bounded from the relative pose: x_o = M v + o
// with M = R_o^T R_s s_s / s_o and o = R_o^T (p_s - p_o) / s_o, so
// |dx_o| <= |M - M0|_F |v| + |o - o0|, |v| at most the largest norm of the
// candidate edges' ends (`reach`). The candidate lists (the vertices near
// the contact and their planes, sorted: patch.cpp) must be the same lists,
// since they fix the edges tried and the lines' order. Measured on a
// sheared packing of 2000-face grains (a 607-grain direct shear at 100 kPa),
// the lists changed in 0.2 % of the steps and the motion used up the
// margin in 6 %: 94 % of the touching pairs' steps reused the cache.
//
// The cache is a pure accelerator: any state of it, cold or stale, gives
// the bits a call without it gives (tests/collision/patch_cache_test.cpp),
// so it is not checkpointed, and a copy of a pair's cache (a World copied, a
// pair carried over by the broadphase) is a deep copy.
#pragma once

#include "core/types.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace grainlab {

class ConvexPolytope;

struct PatchCache {
  // The lists the patch was found with (patch.cpp: collect, gather_planes).
  std::vector<Index> verts[2], planes[2];  // [0]: A's vertices, B's planes; [1]: B's vertices, A's planes
  // Per side, the edges to walk (their two ends, in the order the full walk
  // takes them) and for each its kept lines (positions in planes[side]).
  struct Edge {
    Index v, w;
    std::uint32_t first, count;  // into lines[side]
  };
  std::vector<Edge> edges[2];
  std::vector<std::uint32_t> lines[2];
  // Side s seen from the other body o at the fill: x_o = to_o v + off.
  Mat3 to_o[2];
  Vec3 off[2];
  double reach[2] = {0, 0};   // largest |v| of the edges' ends (s's local units)
  double margin[2] = {0, 0};  // o's local units (see above)
  const ConvexPolytope* hulls[2] = {nullptr, nullptr};
  bool filled = false;
};

// A PairCache member: owns its PatchCache; copies are deep, moves are cheap.
class PatchCacheSlot {
 public:
  PatchCacheSlot() = default;
  PatchCacheSlot(const PatchCacheSlot& o) : p_(o.p_ ? std::make_unique<PatchCache>(*o.p_) : nullptr) {}
  PatchCacheSlot& operator=(const PatchCacheSlot& o) {
    if (this != &o) p_ = o.p_ ? std::make_unique<PatchCache>(*o.p_) : nullptr;
    return *this;
  }
  PatchCacheSlot(PatchCacheSlot&&) noexcept = default;
  PatchCacheSlot& operator=(PatchCacheSlot&&) noexcept = default;
  // The cache, made on first use.
  PatchCache* get() {
    if (!p_) p_ = std::make_unique<PatchCache>();
    return p_.get();
  }
  void clear() { p_.reset(); }

 private:
  std::unique_ptr<PatchCache> p_;
};

}  // namespace grainlab
