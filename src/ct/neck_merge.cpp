#include "ct/neck_merge.h"

#include <algorithm>
#include <map>
#include <numeric>
#include <utility>

namespace grainlab::ct {

RegionGraph region_graph(const std::vector<std::uint32_t>& labels, const Size3& size,
                         const std::vector<float>& distance) {
  const std::uint32_t top = labels.empty() ? 0 : *std::max_element(labels.begin(), labels.end());
  RegionGraph g;
  g.radius.assign(static_cast<std::size_t>(top) + 1, 0.0f);
  for (std::size_t i = 0; i < labels.size(); ++i) g.radius[labels[i]] = std::max(g.radius[labels[i]], distance[i]);
  // Every boundary, over the face pairs along x, y and z.
  std::map<std::pair<std::uint32_t, std::uint32_t>, RegionBoundary> found;
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
          RegionBoundary& r = found[{std::min(a, b), std::max(a, b)}];
          r.a = std::min(a, b);
          r.b = std::max(a, b);
          ++r.faces;
          r.saddle = std::max(r.saddle, std::min(distance[p], distance[q]));
        }
      }
    }
  }
  for (const auto& [key, r] : found) g.boundaries.push_back(r);
  return g;
}

int merge_over_split_regions(std::vector<std::uint32_t>& labels, const Size3& size,
                             const std::vector<float>& distance, double ratio) {
  const RegionGraph graph = region_graph(labels, size, distance);
  std::vector<float> radius = graph.radius;
  std::vector<std::uint32_t> parent(radius.size());
  std::iota(parent.begin(), parent.end(), 0u);
  auto root = [&](std::uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  int merges = 0;
  for (;;) {
    // The boundaries between the current regions, and the most grain-like one.
    std::map<std::pair<std::uint32_t, std::uint32_t>, RegionBoundary> current;
    for (const RegionBoundary& r : graph.boundaries) {
      const std::uint32_t a = root(r.a), b = root(r.b);
      if (a == b) continue;
      RegionBoundary& c = current[{std::min(a, b), std::max(a, b)}];
      c.saddle = std::max(c.saddle, r.saddle);
      c.faces += r.faces;
    }
    double best = -1;
    std::pair<std::uint32_t, std::uint32_t> pick{0, 0};
    for (const auto& [key, c] : current) {
      const double r = std::max(1e-6f, std::min(radius[key.first], radius[key.second]));
      const double score = c.saddle / r;
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
