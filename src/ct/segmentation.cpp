#include "ct/segmentation.h"

#include "core/error.h"
#include "core/parallel.h"
#include "ct/itk_bridge.h"
#include "ct/neck_merge.h"
#include "ct/otsu.h"
#include "ct/regions.h"
#include "geometry/convex_hull.h"
#include "geometry/mass_properties.h"
#include "geometry/shape_metrics.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <fstream>
#include <mutex>
#include <numbers>
#include <sstream>

namespace grainlab::ct {

void validate(const SegmentOptions& o) {
  if (!(o.h >= 0 && std::isfinite(o.h))) {
    input_error("--h {} must be 0 or more voxels (0, the default, chooses it from the grains' size)", o.h);
  }
  if (!(o.merge_ratio >= 0 && o.merge_ratio <= 1)) {
    input_error("--merge-ratio {} must be 0 (no merging) to 1 (merge only where a boundary is as thick as the grain)",
                o.merge_ratio);
  }
  if (o.min_voxels < 1) input_error("--min-voxels {} must be at least 1", o.min_voxels);
  if (o.meshing.faces < 20) input_error("--faces {} must be at least 20", o.meshing.faces);
  if (o.meshing.smooth_iterations < 0) input_error("--smooth {} must be 0 or more", o.meshing.smooth_iterations);
  if (o.threshold && !std::isfinite(*o.threshold)) input_error("--threshold must be a finite grey level");
}

std::uint64_t estimated_bytes(const Size3& size) {
  return static_cast<std::uint64_t>(size[0]) * size[1] * size[2] * kBytesPerVoxel;
}

void check_memory(const Size3& size, const std::string& image_name, std::uint64_t read_buffer_bytes) {
  const std::uint64_t need = estimated_bytes(size) + read_buffer_bytes, have = available_memory_bytes();
  if (have > 0 && need > have) {
    input_error("'{}' is too large for this machine's memory: {} x {} x {} voxels need about {:.1f} GiB for the "
                "segmentation ({} bytes per voxel{}), and {:.1f} GiB is available; crop the volume to the region of "
                "interest (--crop x0,y0,z0,x1,y1,z1), bin it 2x2x2 (--bin 2: 8x less) or use a machine with more "
                "memory{}",
                image_name, size[0], size[1], size[2], need / 1073741824.0, kBytesPerVoxel,
                read_buffer_bytes ? fmt::format(", plus {:.1f} GiB to read the whole file before cropping",
                                                read_buffer_bytes / 1073741824.0)
                                  : std::string(),
                have / 1073741824.0,
                read_buffer_bytes ? " (a folder of slices or a raw file is read a slice at a time)" : "");
  }
}

namespace {

// Steps 4-6: tidy the labels, mesh and measure every grain.
void mesh_and_measure(LabelVolume& labels, const std::optional<GreyField>& grey, const SegmentOptions& options,
                      Progress& progress, Segmentation& result) {
  progress.start("regions");
  const std::size_t before = [&] {
    std::vector<char> seen;
    std::size_t count = 0;
    for (std::uint32_t l : labels.values) {
      if (l >= seen.size()) seen.resize(static_cast<std::size_t>(l) + 1, 0);
      if (l && !seen[l]) {
        seen[l] = 1;
        ++count;
      }
    }
    return count;
  }();
  const std::vector<Region> regions = relabel_regions(labels, options.min_voxels);
  result.dropped_regions = static_cast<int>(before - regions.size());
  progress.finish();
  if (regions.empty()) {
    input_error("no grain of at least {} voxels (--min-voxels) was found ({} smaller regions); check the threshold "
                "and --min-voxels",
                options.min_voxels, before);
  }

  progress.start(fmt::format("meshing {} grains", regions.size()));
  result.grains.resize(regions.size());
  std::vector<std::exception_ptr> errors(regions.size());
  std::atomic<int> done{0};
  std::mutex report;
  parallel_for(static_cast<std::ptrdiff_t>(regions.size()), [&](std::ptrdiff_t i) {
    try {
      const Region& r = regions[i];
      GrainMesh gm = mesh_grain(labels, r, grey, options.meshing);
      SegmentedGrain& g = result.grains[i];
      g.id = static_cast<int>(r.label);
      g.voxels = r.voxels;
      g.border = r.border;
      g.dropped_pieces = gm.dropped_pieces;
      g.within_budget = gm.within_budget;
      const MassProperties mp = mass_properties(gm.mesh);
      g.volume = mp.volume;
      g.centroid = mp.centroid;
      g.equivalent_diameter = std::cbrt(6 * mp.volume / std::numbers::pi);
      Quat q(principal_frame(gm.mesh).axes);
      if (q.w() < 0) q.coeffs() = -q.coeffs();
      g.orientation = q.normalized();
      g.quality.convexity = convexity(gm.mesh);
      g.mesh = std::move(gm.mesh);
    } catch (...) {
      errors[i] = std::current_exception();
    }
    const int d = ++done;
    if (report.try_lock()) {
      progress.report(static_cast<double>(d) / regions.size());
      report.unlock();
    }
  }, 1, options.threads);
  for (const auto& e : errors) {
    if (e) std::rethrow_exception(e);
  }
  progress.finish();

  progress.start("quality table");
  std::vector<GrainQuality> quality(result.grains.size());
  for (std::size_t i = 0; i < quality.size(); ++i) quality[i].convexity = result.grains[i].quality.convexity;
  result.quality_h = assess_grains(labels, regions, result.from_labels ? options.h : result.h, quality);
  for (std::size_t i = 0; i < quality.size(); ++i) result.grains[i].quality = quality[i];
  progress.finish();
  if (options.keep_labels) result.labels = std::move(labels);
}

}  // namespace

Segmentation segment_grey(const GreyVolume& grey, const SegmentOptions& options, Progress& progress) {
  validate(options);
  Segmentation result;
  const auto [lo_it, hi_it] = std::minmax_element(grey.values.begin(), grey.values.end());
  if (lo_it == grey.values.end()) input_error("the image has no voxels");
  for (float v : grey.values) {
    if (!std::isfinite(v)) input_error("the image holds a non-finite grey level ({}): fix or clip the scan", v);
  }
  const float lo = *lo_it, hi = *hi_it;
  if (lo == hi) {
    input_error("the image is all one grey level ({}): there is nothing to segment (an empty or failed "
                "reconstruction?)",
                lo);
  }

  // 1. Threshold.
  progress.start("threshold");
  OtsuResult t;
  if (options.threshold) {
    if (!(*options.threshold >= lo && *options.threshold < hi)) {
      input_error("--threshold {} is outside the image's grey levels [{}, {}): pick a level between the pore and "
                  "the grain grey levels, or leave it out for Otsu's",
                  *options.threshold, lo, hi);
    }
    t = class_means(grey.values, *options.threshold);
  } else {
    t = otsu_threshold(grey.values);
    result.otsu = true;
  }
  result.threshold = t.threshold;
  result.pore_level = t.background_mean;
  result.solid_level = t.foreground_mean;
  MaskVolume mask = threshold_mask(grey, t.threshold);

  // 2. Fill small enclosed pores.
  result.filled_voxels = fill_small_pores(mask, options.min_voxels);
  const std::int64_t solid = std::count(mask.values.begin(), mask.values.end(), 1);
  result.solid_fraction = static_cast<double>(solid) / mask.voxel_count();
  progress.finish();
  if (solid == 0 || solid == mask.voxel_count()) {
    input_error("every voxel is {} at threshold {}: no {} to separate grains; give a --threshold between the pore "
                "and grain grey levels",
                solid == 0 ? "pore" : "solid", t.threshold, solid == 0 ? "solid" : "pore");
  }

  // 3. Distance-transform watershed.
  progress.start("distance map and watershed");
  LabelVolume labels;
  labels.copy_grid(grey);
  itk_bridge::Watershed split =
      itk_bridge::distance_watershed(mask.values, grey.size, options.h, [&](double f) { progress.report(f); },
                                     options.merge_ratio > 0 ? kOverSplitDepth : 0.0);
  labels.values = std::move(split.labels);
  if (options.merge_ratio > 0) {
    result.merged_regions = merge_over_split_regions(labels.values, labels.size, split.distance, options.merge_ratio);
  }
  result.h = split.h;
  result.typical_radius = split.typical_radius;
  mask.values = {};
  progress.finish();

  // 4-6.
  GreyField field{&grey, t.threshold, static_cast<float>(t.background_mean), static_cast<float>(t.foreground_mean)};
  mesh_and_measure(labels, field, options, progress, result);
  return result;
}

Segmentation segment_labels(LabelVolume labels, const SegmentOptions& options, Progress& progress) {
  validate(options);
  Segmentation result;
  result.from_labels = true;
  const std::int64_t solid = labels.voxel_count() - std::count(labels.values.begin(), labels.values.end(), 0u);
  if (solid == 0) input_error("the label image is all 0 (pore): it labels no grain");
  result.solid_fraction = static_cast<double>(solid) / labels.voxel_count();
  mesh_and_measure(labels, std::nullopt, options, progress, result);
  return result;
}

}  // namespace grainlab::ct
