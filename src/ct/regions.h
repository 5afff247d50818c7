// Binary masks and labelled regions: thresholding, filling small pores inside
// the solid, and the tidy list of grains a watershed leaves.
#pragma once

#include "ct/volume.h"

#include <vector>

namespace grainlab::ct {

// 1 where value > threshold.
MaskVolume threshold_mask(const GreyVolume& grey, float threshold);

// Makes solid every pore region (6-connected) that does not touch the image
// border and has fewer than `max_voxels` voxels: noise specks and tiny
// cavities inside grains. Returns the number of voxels filled.
std::int64_t fill_small_pores(MaskVolume& mask, std::int64_t max_voxels);

// One labelled region (a grain).
struct Region {
  std::uint32_t label = 0;              // 1..n after relabel_regions
  std::int64_t voxels = 0;
  Size3 lo{0, 0, 0}, hi{0, 0, 0};       // inclusive voxel bounding box
  bool border = false;                  // has a voxel on a face of the image
};

// Clears regions with fewer than `min_voxels` voxels, numbers the rest 1..n in
// the order of their first voxel (z, then y, then x), and describes them.
std::vector<Region> relabel_regions(LabelVolume& labels, std::int64_t min_voxels);

}  // namespace grainlab::ct
