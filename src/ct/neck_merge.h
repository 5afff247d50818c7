// Merging an over-segmented watershed back along boundaries that cut through
// a grain rather than along contacts between grains.
//
// With d the distance map inside the solid (voxels), each region R has its
// largest inscribed radius r_R = max over R of d. Two adjacent regions a, b
// share a boundary (voxel faces between them); its saddle s_ab is the largest
// min(d(p), d(q)) over the boundary's face pairs (p in a, q in b): the radius
// of the fattest ball passing through it. A contact between two grains is a
// neck where the solid pinches: the ball through it is much smaller than
// either grain's own ball, s_ab << min(r_a, r_b). A boundary the watershed
// drew inside one grain (two hills of an elongated or dented grain's distance
// map) crosses the grain's full section: s_ab stays close to the smaller
// region's own radius. So a, b are one grain when
//     s_ab >= ratio * min(r_a, r_b).
// On the eight-grain phantoms of docs/ct.md (24 and 36 voxels across, seeds
// 1-4: 52 boundaries of the 0.5-deep over-split) the cuts inside a grain had
// s/r 0.83-0.95, the contacts 0.17-0.88 (one above 0.78: a small grain
// pressed 2.5 voxels into a larger one). The boundary's area A (voxel faces)
// over pi r^2 was 2.86-4.16 for the cuts and 0.08-2.58 for the contacts, so
// adding A >= 2.7 pi r^2 separated all 52 there; it is not used: a cut across
// a round section (a capsule cut at its middle, A = pi r^2) would stay split,
// and the figures are those the threshold would be tuned on.
// The ratio test is the h-maxima test min(r_a, r_b) - s_ab <= h with h made
// relative to each pair's own size, rather than one depth for the whole scan: a thin
// elongated grain and a thick one each get the depth their own radius calls
// for. Pairs are merged greedily, highest s_ab / min(r_a, r_b) first; after a
// merge the union's radius is the larger and its boundaries with a third
// region are the union of the two (saddle: the larger; faces: the sum).
#pragma once

#include "ct/volume.h"

#include <cstdint>
#include <vector>

namespace grainlab::ct {

// Two adjacent regions' shared boundary: voxel faces between them, and its saddle (voxels).
struct RegionBoundary {
  std::uint32_t a = 0, b = 0;  // a < b
  std::int64_t faces = 0;
  float saddle = 0;
};
struct RegionGraph {
  std::vector<float> radius;             // largest inscribed radius (voxels) by label ([0]: the pore)
  std::vector<RegionBoundary> boundaries;
};
RegionGraph region_graph(const std::vector<std::uint32_t>& labels, const Size3& size,
                         const std::vector<float>& distance);

// Relabels `labels` (0 = pore) in place, merging regions as above with the
// distance map `distance` (same grid, voxels). Returns the number of merges.
int merge_over_split_regions(std::vector<std::uint32_t>& labels, const Size3& size,
                             const std::vector<float>& distance, double ratio);

}  // namespace grainlab::ct
