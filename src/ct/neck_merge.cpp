#include "ct/neck_merge.h"

#include <algorithm>
#include <map>
#include <numeric>
#include <utility>

namespace grainlab::ct {

int merge_over_split_regions(std::vector<std::uint32_t>& labels, const Size3& size,
                             const std::vector<float>& distance, double ratio) {
  const std::uint32_t top = labels.empty() ? 0 : *std::max_element(labels.begin(), labels.end());
  std::vector<float> radius(static_cast<std::size_t>(top) + 1, 0.0f);
  for (std::size_t i = 0; i < labels.size(); ++i) radius[labels[i]] = std::max(radius[labels[i]], distance[i]);

  // Saddle of every boundary, over the face pairs along x, y and z.
  std::map<std::pair<std::uint32_t, std::uint32_t>, float> saddle;
  const std::int64_t nx = size[0], ny = size[1], nz = size[2];
  const std::int64_t step[3] = {1, nx, nx * ny};
  for (std::int64_t k = 0; k < nz; ++k) {
    for (std::int64_t j = 0; j < ny; ++j) {
      for (std::int64_t i = 0; i < nx; ++i) {
        const std::size_t p = static_cast<std::size_t>(i + nx * (j + ny * k));
        const std::uint32_t a = labels[p];
        if (!a) continue;
        const bool next[3] = {i + 1 < nx, j + 1 < ny, k + 1 < nz};
        for (int ax = 0; ax < 3; ++ax) {
          if (!next[ax]) continue;
          const std::size_t q = p + static_cast<std::size_t>(step[ax]);
          const std::uint32_t b = labels[q];
          if (!b || b == a) continue;
          float& s = saddle[{std::min(a, b), std::max(a, b)}];
          s = std::max(s, std::min(distance[p], distance[q]));
        }
      }
    }
  }

  std::vector<std::uint32_t> parent(radius.size());
  std::iota(parent.begin(), parent.end(), 0u);
  auto root = [&](std::uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  int merges = 0;
  for (;;) {
    // The boundaries between the current regions, and the most grain-like one.
    std::map<std::pair<std::uint32_t, std::uint32_t>, float> current;
    for (const auto& [key, s] : saddle) {
      const std::uint32_t a = root(key.first), b = root(key.second);
      if (a == b) continue;
      float& c = current[{std::min(a, b), std::max(a, b)}];
      c = std::max(c, s);
    }
    double best = -1;
    std::pair<std::uint32_t, std::uint32_t> pick{0, 0};
    for (const auto& [key, s] : current) {
      const double score = s / std::max(1e-6f, std::min(radius[key.first], radius[key.second]));
      if (score > best) {
        best = score;
        pick = key;
      }
    }
    if (best < ratio) break;
    parent[pick.second] = pick.first;
    radius[pick.first] = std::max(radius[pick.first], radius[pick.second]);
    ++merges;
  }
  if (merges) {
    for (std::uint32_t& l : labels) l = root(l);
  }
  return merges;
}

}  // namespace grainlab::ct
