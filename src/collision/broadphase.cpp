// Sweep and prune.
//
// Bodies are kept sorted by the lower end of their box along one axis. Each
// call refreshes the keys, re-sorts by insertion sort (nearly O(n) when the
// scene moved a little since the last call), then sweeps: body k can only
// overlap the bodies after it whose lower end is at most its upper end. The
// candidates are tested on all three axes and the pairs sorted by (i, j), so
// the output does not depend on the sort order or on the history.
#include "collision/broadphase.h"

#include <algorithm>
#include <numeric>

namespace grainlab {

namespace {

// Spread (variance) of the box centres along each axis.
Vec3 centre_variance(std::span<const Aabb> boxes) {
  Vec3 sum = Vec3::Zero(), sum2 = Vec3::Zero();
  for (const Aabb& b : boxes) {
    const Vec3 c = 0.5 * (b.lo + b.hi);
    sum += c;
    sum2 += c.cwiseProduct(c);
  }
  const double n = static_cast<double>(boxes.size());
  const Vec3 mean = sum / n;
  return (sum2 / n - mean.cwiseProduct(mean)).cwiseMax(0.0);
}

}  // namespace

void SweepAndPrune::find_pairs(std::span<const Aabb> boxes, std::vector<BodyPair>& pairs) {
  pairs.clear();
  const Index n = static_cast<Index>(boxes.size());
  if (n < 2) {
    order_.clear();
    return;
  }

  // Axis of largest spread, switched only when another axis is clearly
  // better, so that the kept order stays useful from call to call.
  const Vec3 var = centre_variance(boxes);
  int best = 0;
  var.maxCoeff(&best);
  bool resort = static_cast<Index>(order_.size()) != n;
  if (best != axis_ && var[best] > 1.5 * var[axis_]) {
    axis_ = best;
    resort = true;
  }
  const int ax = axis_;

  if (resort) {
    order_.resize(static_cast<std::size_t>(n));
    std::iota(order_.begin(), order_.end(), Index{0});
    std::sort(order_.begin(), order_.end(), [&](Index a, Index b) {
      const double la = boxes[a].lo[ax], lb = boxes[b].lo[ax];
      return la < lb || (la == lb && a < b);
    });
  } else {
    // Insertion sort on the kept order (ties broken by body index).
    for (Index k = 1; k < n; ++k) {
      const Index body = order_[k];
      const double key = boxes[body].lo[ax];
      Index m = k;
      while (m > 0) {
        const Index prev = order_[m - 1];
        const double pk = boxes[prev].lo[ax];
        if (pk < key || (pk == key && prev < body) || !(pk == pk)) break;
        order_[m] = prev;
        --m;
      }
      order_[m] = body;
    }
  }

  // Sweep on contiguous copies of the sorted boxes (sweep axis first).
  const int a1 = (ax + 1) % 3, a2 = (ax + 2) % 3;
  sorted_.resize(static_cast<std::size_t>(n));
  for (Index k = 0; k < n; ++k) {
    const Aabb& b = boxes[order_[k]];
    sorted_[k] = {b.lo[ax], b.hi[ax], b.lo[a1], b.hi[a1], b.lo[a2], b.hi[a2]};
  }
  for (Index k = 0; k < n; ++k) {
    const SortedBox bk = sorted_[k];
    for (Index m = k + 1; m < n && sorted_[m].lo0 <= bk.hi0; ++m) {
      const SortedBox& bm = sorted_[m];
      if (bk.lo1 <= bm.hi1 && bm.lo1 <= bk.hi1 && bk.lo2 <= bm.hi2 && bm.lo2 <= bk.hi2) {
        const Index i = order_[k], j = order_[m];
        pairs.emplace_back(std::min(i, j), std::max(i, j));
      }
    }
  }
  std::sort(pairs.begin(), pairs.end());
}

void brute_force_pairs(std::span<const Aabb> boxes, std::vector<BodyPair>& pairs) {
  pairs.clear();
  const Index n = static_cast<Index>(boxes.size());
  for (Index i = 0; i < n; ++i)
    for (Index j = i + 1; j < n; ++j)
      if (boxes[i].overlaps(boxes[j])) pairs.emplace_back(i, j);
}

}  // namespace grainlab
