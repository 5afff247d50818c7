#include "ct/regions.h"

#include <algorithm>

namespace grainlab::ct {

MaskVolume threshold_mask(const GreyVolume& grey, float threshold) {
  MaskVolume mask;
  mask.copy_grid(grey);
  mask.values.resize(grey.values.size());
  std::transform(grey.values.begin(), grey.values.end(), mask.values.begin(),
                 [threshold](float v) { return static_cast<std::uint8_t>(v > threshold); });
  return mask;
}

std::int64_t fill_small_pores(MaskVolume& mask, std::int64_t max_voxels) {
  const std::int64_t nx = mask.size[0], ny = mask.size[1], nz = mask.size[2];
  std::vector<char> seen(mask.values.size(), 0);
  std::vector<std::size_t> region, stack;
  std::int64_t filled = 0;
  for (std::size_t start = 0; start < mask.values.size(); ++start) {
    if (mask.values[start] || seen[start]) continue;
    // Flood one pore region, noting whether it reaches the border; stop collecting past max_voxels.
    region.clear();
    stack.assign(1, start);
    seen[start] = 1;
    bool border = false;
    std::int64_t count = 0;
    while (!stack.empty()) {
      const std::size_t v = stack.back();
      stack.pop_back();
      ++count;
      if (count < max_voxels) region.push_back(v);
      const std::int64_t i = static_cast<std::int64_t>(v % nx), j = static_cast<std::int64_t>((v / nx) % ny),
                         k = static_cast<std::int64_t>(v / (nx * ny));
      if (i == 0 || j == 0 || k == 0 || i == nx - 1 || j == ny - 1 || k == nz - 1) border = true;
      const std::int64_t step[3] = {1, nx, nx * ny};
      const std::int64_t idx[3] = {i, j, k}, n[3] = {nx, ny, nz};
      for (int a = 0; a < 3; ++a) {
        for (int s = -1; s <= 1; s += 2) {
          const std::int64_t c = idx[a] + s;
          if (c < 0 || c >= n[a]) continue;
          const std::size_t w = static_cast<std::size_t>(static_cast<std::int64_t>(v) + s * step[a]);
          if (!mask.values[w] && !seen[w]) {
            seen[w] = 1;
            stack.push_back(w);
          }
        }
      }
    }
    if (!border && count < max_voxels) {
      for (std::size_t v : region) mask.values[v] = 1;
      filled += count;
    }
  }
  return filled;
}

std::vector<Region> relabel_regions(LabelVolume& labels, std::int64_t min_voxels) {
  const std::uint32_t top = labels.values.empty() ? 0 : *std::max_element(labels.values.begin(), labels.values.end());
  std::vector<Region> found(static_cast<std::size_t>(top) + 1);
  std::vector<char> fresh(found.size(), 1);
  std::vector<std::uint32_t> order;
  const std::int64_t nx = labels.size[0], ny = labels.size[1], nz = labels.size[2];
  for (std::int64_t k = 0; k < nz; ++k) {
    for (std::int64_t j = 0; j < ny; ++j) {
      for (std::int64_t i = 0; i < nx; ++i) {
        const std::uint32_t l = labels.at(i, j, k);
        if (!l) continue;
        Region& r = found[l];
        if (fresh[l]) {
          fresh[l] = 0;
          order.push_back(l);
          r.label = l;
          r.lo = {i, j, k};
          r.hi = {i, j, k};
        }
        ++r.voxels;
        const std::int64_t idx[3] = {i, j, k};
        for (int a = 0; a < 3; ++a) {
          r.lo[a] = std::min(r.lo[a], idx[a]);
          r.hi[a] = std::max(r.hi[a], idx[a]);
        }
      }
    }
  }
  std::vector<std::uint32_t> renumber(found.size(), 0);
  std::vector<Region> kept;
  for (std::uint32_t l : order) {
    Region r = found[l];
    if (r.voxels < min_voxels) {
      renumber[l] = 0;
      continue;
    }
    r.label = static_cast<std::uint32_t>(kept.size() + 1);
    renumber[l] = r.label;
    for (int a = 0; a < 3; ++a) {
      if (r.lo[a] == 0 || r.hi[a] == labels.size[a] - 1) r.border = true;
    }
    kept.push_back(r);
  }
  for (std::uint32_t& l : labels.values) {
    if (l) l = renumber[l];
  }
  return kept;
}

}  // namespace grainlab::ct
