// What a touching pair of polytopes keeps of its contact patch between steps
// (patch.cpp): a Verlet list of contact features. For each body s, the edges
// of s that may reach inside the other body o, and for each of them the few
// face planes of o whose distance lines may matter to the lower envelope of
// its depth. A cached call walks only those edges over those lines instead
// of classing every edge at the contact against every candidate plane.
//
// Why the result is the same bits. Along an edge x(t), t in [0, 1], of s,
// seen in o's local frame, the depth inside o is the lower envelope
// E(t) = min_k l_k(t) of the lines l_k(t) = c_k - m_k . x(t) (|m_k| = 1)
// over o's candidate planes P (patch.cpp). At the fill, with a skin delta:
//  - an edge is kept unless one plane, or U = min_k max(l_k(0), l_k(1)),
//    puts it at least delta outside o (U >= max E);
//  - on a kept edge, line k is kept if its gap min_t (l_k(t) - E(t)) is
//    below delta (l_k - E is convex and piecewise linear: its least value
//    is at a corner of E or an end), or if max(l_k(0), l_k(1)) < U + delta.
// Since then every point of s has moved by at most b in o's frame, so every
// l_k(t), E(t) and U by at most b. While 2 b + tie < delta and P is the same
// set, a left-out edge still has U < 0: patch.cpp skips it (U <= 0) and adds
// nothing; and on a kept edge the lines of E, the line that gives U and the
// lines lowest at either end are all kept, so U, both ends' minima and the
// first plane (in P's order) attaining them are the same, the line filter
// keeps the same kept lines, and the lines left out lie at least `tie`
// above E on the whole edge: they can never be the walk's next line nor
// tie with it within its 1e-12 (their crossings with the current line are
// far past its end). The walk over the kept lines, in the order of the call's
// own P, takes the same lines and crossings and adds the same pieces in the
// same order as the walk over all of P: the same rounding. P is the set of
// o's planes through o's candidate vertices, so it is the same set when both
// bodies' candidate vertex sets are (checked each call); their order, which
// fixes the order of edges and lines (and of the sums), is the call's own.
// b is bounded from the relative pose: x_o = M v + off with
// M = R_o^T R_s s_s / s_o and off = R_o^T (p_s - p_o) / s_o, so
// |dx_o| <= |M - M0|_F |v| + |off - off0|, |v| at most s's bounding radius.
//
// The skin adapts to the motion: a fill sizes delta for kTargetUses calls at
// the motion per call measured since the last fill (or over one call before
// the first), within [kMinSkin, kMaxSkin] of the grain size; a cache that
// dies after fewer than kMinUses calls (a falling grain: its candidate sets
// change every step or two) makes the pair skip filling for 2, 4, ... 64
// calls, so a fast pair pays almost nothing and a sheared packing keeps.
//
// A pure accelerator: any state of it, cold or stale, gives the bits a call
// without it gives (tests/collision/patch_cache_test.cpp), so it is not
// checkpointed, and a copy of a pair's cache starts cold (a move keeps it).
#pragma once

#include "core/types.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace grainlab {

class ConvexPolytope;

struct PatchCache {
  static constexpr std::uint32_t kTargetUses = 32;  // calls a fill's skin is sized for
  static constexpr std::uint32_t kMinUses = 2;      // a fill that served fewer backs off
  static constexpr std::uint32_t kMaxSkip = 64;     // longest back-off (calls)
  static constexpr double kMinSkin = 1e-6;          // skin bounds, fractions of the grain's bounding radius
  static constexpr double kMaxSkin = 2e-3;
  static constexpr double kTie = 1e-9;              // gap kept for the walk's ties (patch.cpp), fraction of size

  // An edge of s kept, from v (the end the full walk takes it from) to w;
  // its kept lines are planes of o, lines[first .. first + count).
  struct Edge {
    Index v, w;
    std::uint32_t first, count;
  };
  // One body s (0: A, 1: B) seen from the other, o.
  struct Side {
    std::vector<Index> verts;    // s's candidate vertices at the fill (a set)
    std::vector<Edge> edges;     // in the full walk's order at the fill (grouped by v)
    std::vector<Index> lines;    // planes of o
    Mat3 to_o = Mat3::Identity();  // x_o = to_o v + off at the fill (or the probe)
    Vec3 off = Vec3::Zero();
    double skin = 0;  // delta, o's local units
    double tie = 0;   // o's local units
  };
  Side side[2];
  const ConvexPolytope* hulls[2] = {nullptr, nullptr};
  enum class Phase : std::uint8_t { kCold, kProbed, kFilled } phase = Phase::kCold;
  std::uint32_t uses = 0;   // cached calls since the fill (probe: calls since the probe)
  std::uint32_t skip = 0;   // calls left before the next probe
  std::uint32_t fails = 0;  // fills in a row that served fewer than kMinUses calls
  std::uint32_t fill_count = 0, use_count = 0;  // fills and cached calls in all (statistics)

  // Heap bytes held (for the memory figures).
  std::size_t memory_bytes() const {
    std::size_t n = sizeof(PatchCache);
    for (const Side& s : side)
      n += s.verts.capacity() * sizeof(Index) + s.edges.capacity() * sizeof(Edge) + s.lines.capacity() * sizeof(Index);
    return n;
  }
};

// A PairCache member: owns its PatchCache, made on first use. A copy starts
// cold (the cache never changes a result); a move keeps it.
class PatchCacheSlot {
 public:
  PatchCacheSlot() = default;
  PatchCacheSlot(const PatchCacheSlot&) {}
  PatchCacheSlot& operator=(const PatchCacheSlot& o) {
    if (this != &o) p_.reset();
    return *this;
  }
  PatchCacheSlot(PatchCacheSlot&&) noexcept = default;
  PatchCacheSlot& operator=(PatchCacheSlot&&) noexcept = default;
  PatchCache* get() {
    if (!p_) p_ = std::make_unique<PatchCache>();
    return p_.get();
  }
  const PatchCache* peek() const { return p_.get(); }

 private:
  std::unique_ptr<PatchCache> p_;
};

}  // namespace grainlab
