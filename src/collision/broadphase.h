// Broadphase: which pairs of boxes overlap.
#pragma once

#include "collision/aabb.h"

#include <span>
#include <utility>
#include <vector>

namespace grainlab {

using BodyPair = std::pair<Index, Index>;  // first < second

// Sweep and prune along the axis of largest spread. The sorted endpoint order
// is kept between calls, so a scene that moved a little is re-sorted by
// insertion sort in nearly O(n).
class SweepAndPrune {
 public:
  // All pairs (i < j) whose boxes overlap, sorted by (i, j).
  void find_pairs(std::span<const Aabb> boxes, std::vector<BodyPair>& pairs);

 private:
  std::vector<Index> order_;  // bodies sorted by lo along axis_ (kept between calls)
  struct SortedBox { double lo0, hi0, lo1, hi1, lo2, hi2; };  // sweep axis first
  std::vector<SortedBox> sorted_;  // boxes in sorted order (sweep scratch)
  int axis_ = 0;
};

// O(n^2) reference, sorted by (i, j): for tests.
void brute_force_pairs(std::span<const Aabb> boxes, std::vector<BodyPair>& pairs);

}  // namespace grainlab
