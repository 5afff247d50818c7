// X-ray CT volume to grains: the recipe of `grainlab ct segment`.
//
//  1. threshold: solid where grey > T (Otsu's T unless given);
//  2. clean: pores smaller than min_voxels enclosed by solid become solid;
//  3. split: distance-transform watershed with h-maxima markers (depth h voxels,
//     by default scaled with the grains' inscribed radius);
//  4. tidy: regions smaller than min_voxels are dropped, the rest numbered 1..n;
//  5. mesh: each grain's iso-surface, Taubin-smoothed, simplified to the face
//     budget and checked;
//  6. measure: volume, centroid and principal frame of each mesh, and the
//     quality indicators (grain_quality.h): convexity, distance maxima,
//     contacts with the neighbouring labels, likely merges and splits.
// A label image (already segmented) starts at step 4.
#pragma once

#include "core/available_memory.h"
#include "ct/grain_mesher.h"
#include "ct/grain_quality.h"
#include "ct/progress.h"
#include "ct/volume.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace grainlab::ct {

// The merge step's defaults (docs/ct.md, step 3): on packed elongated, dented
// grains at 24 and 36 voxels across, markers 0.5 voxel deep and a ratio of
// 0.85 found 142 of 144 grains one to one, h-maxima alone 134 (docs/ct.md).
inline constexpr double kMergeRatio = 0.85;
inline constexpr double kOverSplitDepth = 0.5;

struct SegmentOptions {
  std::optional<float> threshold;  // grey level; absent: Otsu
  double h = 0;                    // h-maxima depth (voxels): the smallest neck-to-centre rise that separates
                                   // grains; 0: a fifth of the median inscribed radius (itk_bridge.h)
  std::int64_t min_voxels = 100;   // smaller regions are noise; smaller enclosed pores are filled
  int threads = 0;                 // worker threads meshing the grains (0 = all cores)
  double merge_ratio = kMergeRatio; // > 0: split with depth kOverSplitDepth, then merge adjacent regions whose
                                   // boundary's saddle is at least this fraction of the smaller one's
                                   // inscribed radius (neck_merge.h); 0: h-maxima at depth h alone
  bool keep_labels = false;        // keep the label image (Segmentation::labels), for measuring
  MeshingOptions meshing;
};

// Throws InputError naming the option when a value is out of range.
void validate(const SegmentOptions& options);

// One segmented grain, measured on its mesh.
struct SegmentedGrain {
  int id = 0;                       // 1..n, in the order of the grain's first voxel (z, y, x)
  TriMesh mesh;                     // world coordinates (m)
  Vec3 centroid = Vec3::Zero();     // m
  Quat orientation = Quat::Identity();  // rotates x, y, z onto the long, intermediate, short principal axes
  double volume = 0;                // m^3
  double equivalent_diameter = 0;   // m: the sphere of equal volume
  bool border = false;              // touches a face of the image (cut off: its shape is incomplete)
  std::int64_t voxels = 0;          // voxels labelled with it
  int dropped_pieces = 0;           // surface pieces left out (see GrainMesh)
  bool within_budget = true;
  GrainQuality quality;             // merge and split indicators (grain_quality.h)
};

struct Segmentation {
  std::vector<SegmentedGrain> grains;
  bool from_labels = false;
  float threshold = 0;              // grey level used (grey images)
  bool otsu = false;                // the threshold is Otsu's
  double h = 0;                     // h-maxima depth used (voxels; grey images)
  double typical_radius = 0;        // median inscribed radius (voxels) when h was chosen from it (h = 0)
  double pore_level = 0, solid_level = 0;  // class means
  double solid_fraction = 0;        // of the voxels, after cleaning
  std::int64_t filled_voxels = 0;   // pore voxels made solid (step 2)
  int dropped_regions = 0;          // regions below min_voxels (step 4)
  int merged_regions = 0;           // watershed regions merged back (neck_merge.h)
  double quality_h = 0;             // h (voxels) of the distance maxima in the quality table
  LabelVolume labels;               // grain ids 1..n, 0 = pore (only with SegmentOptions::keep_labels)
};

// Steps 1-6 on a grey-level scan. Throws InputError for an image with nothing
// to segment (one grey level, a threshold outside the grey range, no solid or
// no pore, no region of min_voxels).
Segmentation segment_grey(const GreyVolume& grey, const SegmentOptions& options, Progress& progress);

// Steps 4-6 on a label image (0 = pore). Takes the labels by value (renumbers them).
Segmentation segment_labels(LabelVolume labels, const SegmentOptions& options, Progress& progress);

// Bytes the pipeline needs at its peak, per voxel and in all: the grey image,
// the mask, and ITK's distance map, h-maxima, markers and watershed (measured
// on a 256^3 volume, rounded up).
inline constexpr int kBytesPerVoxel = 40;
std::uint64_t estimated_bytes(const Size3& size);

// Throws InputError when estimated_bytes(size) plus `read_buffer_bytes` (held
// while reading, ImageHeader::read_buffer_bytes) exceeds the available memory,
// with both figures and what to do (--crop, --bin 2).
void check_memory(const Size3& size, const std::string& image_name, std::uint64_t read_buffer_bytes = 0);

}  // namespace grainlab::ct
