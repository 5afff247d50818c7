// Per-grain quality indicators of a segmentation (grain_quality.csv): what a
// user checks to find the grains the watershed likely merged or split.
//
//  - convexity: mesh volume / its convex hull's volume. Sand grains are
//    nearly convex (0.9-1); two equal spheres merged at a point give
//    (8/3) / (2 + 4/3) = 0.8 (two balls over their hull, a cylinder of
//    length 2r capped by two half-balls).
//  - distance maxima: hills of the grain's own distance map (distance to any
//    voxel not in the grain) rising more than h above their saddle, with the
//    watershed's h: the markers the watershed would give the grain alone. A
//    grain the watershed made keeps one; two mean two grains under one label
//    (a label image, or a neck the watershed did not cut).
//  - contacts with neighbouring labels: the voxel faces between this label and
//    each other one, times the face's area (s_y s_z for a face normal to x,
//    ...). A staircase overestimates an oblique contact by up to sqrt(3).
//  - largest contact ratio: max over neighbours n of A(g, n) / (pi r^2), r
//    the equivalent radius (from the voxel volume) of the smaller of g and n.
//    Two grains touching at a neck of radius a share about pi a^2, a ratio of
//    (a/r)^2, small; a grain cut in two shares its cross-section, a ratio
//    near 1 or above (a ball cut through its centre: 1.59 for each half).
//
// Flags: likely merge when there are two or more distance maxima or the
// convexity is below kMergeConvexity; likely split when the largest contact
// ratio exceeds kSplitContactRatio. They are hints to look at a grain, not
// verdicts: a strongly dented grain may read as a merge.
#pragma once

#include "ct/regions.h"
#include "ct/volume.h"

#include <vector>

namespace grainlab::ct {

inline constexpr double kMergeConvexity = 0.85;
inline constexpr double kSplitContactRatio = 0.5;

struct GrainQuality {
  double convexity = 1;
  int distance_maxima = 1;
  int contacts = 0;                   // neighbouring labels sharing a voxel face
  double contact_area = 0;            // m^2, all contacts
  double largest_contact_ratio = 0;   // see above
  bool likely_merge = false;
  bool likely_split = false;
};

// The area (m^2) of voxel faces shared by each pair of labels a < b.
struct LabelContact {
  std::uint32_t a = 0, b = 0;
  double area = 0;
};
std::vector<LabelContact> label_contacts(const LabelVolume& labels);

// Fills every field but convexity (given, from the meshes) for the grains of
// `regions` (labels 1..n, regions[i].label == i + 1). h: the watershed depth
// in voxels; 0 chooses it as the watershed does (itk_bridge.h) from the
// grains' inscribed radii. Returns the h used.
double assess_grains(const LabelVolume& labels, const std::vector<Region>& regions, double h,
                     std::vector<GrainQuality>& quality);

}  // namespace grainlab::ct
