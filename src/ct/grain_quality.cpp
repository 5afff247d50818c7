#include "ct/grain_quality.h"

#include "ct/itk_bridge.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

namespace grainlab::ct {

namespace {

// The grain's indicator on its bounding box plus one voxel of margin.
itk_bridge::Hills hills_of(const LabelVolume& labels, const Region& r, double h) {
  std::array<std::int64_t, 3> size{};
  for (int a = 0; a < 3; ++a) size[a] = r.hi[a] - r.lo[a] + 3;
  std::vector<std::uint8_t> mask(static_cast<std::size_t>(size[0] * size[1] * size[2]), 0);
  for (std::int64_t k = r.lo[2]; k <= r.hi[2]; ++k)
    for (std::int64_t j = r.lo[1]; j <= r.hi[1]; ++j)
      for (std::int64_t i = r.lo[0]; i <= r.hi[0]; ++i) {
        if (labels.at(i, j, k) != r.label) continue;
        const std::int64_t x = i - r.lo[0] + 1, y = j - r.lo[1] + 1, z = k - r.lo[2] + 1;
        mask[static_cast<std::size_t>(x + size[0] * (y + size[1] * z))] = 1;
      }
  return itk_bridge::distance_hills(mask, size, h);
}

}  // namespace

std::vector<LabelContact> label_contacts(const LabelVolume& labels) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, double> area;
  const Vec3& s = labels.spacing;
  const double face[3] = {s.y() * s.z(), s.x() * s.z(), s.x() * s.y()};
  const Size3& n = labels.size;
  for (std::int64_t k = 0; k < n[2]; ++k)
    for (std::int64_t j = 0; j < n[1]; ++j)
      for (std::int64_t i = 0; i < n[0]; ++i) {
        const std::uint32_t a = labels.at(i, j, k);
        if (!a) continue;
        const std::uint32_t next[3] = {i + 1 < n[0] ? labels.at(i + 1, j, k) : 0u,
                                       j + 1 < n[1] ? labels.at(i, j + 1, k) : 0u,
                                       k + 1 < n[2] ? labels.at(i, j, k + 1) : 0u};
        for (int axis = 0; axis < 3; ++axis) {
          const std::uint32_t b = next[axis];
          if (b && b != a) area[{std::min(a, b), std::max(a, b)}] += face[axis];
        }
      }
  std::vector<LabelContact> out;
  for (const auto& [pair, A] : area) out.push_back({pair.first, pair.second, A});
  return out;
}

double assess_grains(const LabelVolume& labels, const std::vector<Region>& regions, double h,
                     std::vector<GrainQuality>& quality) {
  quality.resize(regions.size());
  if (h == 0) {  // as the watershed chooses it, from the median inscribed radius
    std::vector<double> radius;
    for (const Region& r : regions) radius.push_back(hills_of(labels, r, 0).radius);
    std::nth_element(radius.begin(), radius.begin() + radius.size() / 2, radius.end());
    h = std::max(itk_bridge::kMinDepth, itk_bridge::kDepthPerRadius * radius[radius.size() / 2]);
  }
  for (std::size_t g = 0; g < regions.size(); ++g) quality[g].distance_maxima = hills_of(labels, regions[g], h).count;

  // Equivalent radius from the voxel volume, the scale of a grain's cross-section.
  const double voxel_volume = labels.spacing.prod();
  std::vector<double> radius(regions.size());
  for (std::size_t g = 0; g < regions.size(); ++g) {
    radius[g] = std::cbrt(3 * regions[g].voxels * voxel_volume / (4 * std::numbers::pi));
  }
  for (const LabelContact& c : label_contacts(labels)) {
    const std::size_t a = c.a - 1, b = c.b - 1;
    const double r = std::min(radius[a], radius[b]);
    const double ratio = c.area / (std::numbers::pi * r * r);
    for (std::size_t g : {a, b}) {
      ++quality[g].contacts;
      quality[g].contact_area += c.area;
      quality[g].largest_contact_ratio = std::max(quality[g].largest_contact_ratio, ratio);
    }
  }
  for (GrainQuality& q : quality) {
    q.likely_merge = q.distance_maxima >= 2 || q.convexity < kMergeConvexity;
    q.likely_split = q.largest_contact_ratio > kSplitContactRatio;
  }
  return h;
}

}  // namespace grainlab::ct
