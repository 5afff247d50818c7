#include "ct/taubin_smooth.h"

#include <algorithm>
#include <vector>

namespace grainlab::ct {

void taubin_smooth(TriMesh& mesh, int iterations, double lambda, double mu) {
  const std::size_t n = mesh.vertices.size();
  // Unique edge neighbours of each vertex, in compressed rows.
  std::vector<std::vector<Index>> adjacent(n);
  for (const Face& f : mesh.faces) {
    for (int c = 0; c < 3; ++c) {
      adjacent[f[c]].push_back(f[(c + 1) % 3]);
      adjacent[f[c]].push_back(f[(c + 2) % 3]);
    }
  }
  for (auto& a : adjacent) {
    std::sort(a.begin(), a.end());
    a.erase(std::unique(a.begin(), a.end()), a.end());
  }
  std::vector<Vec3> next(n);
  auto step = [&](double k) {
    for (std::size_t v = 0; v < n; ++v) {
      if (adjacent[v].empty()) {
        next[v] = mesh.vertices[v];
        continue;
      }
      Vec3 mean = Vec3::Zero();
      for (Index q : adjacent[v]) mean += mesh.vertices[q];
      mean /= static_cast<double>(adjacent[v].size());
      next[v] = mesh.vertices[v] + k * (mean - mesh.vertices[v]);
    }
    mesh.vertices.swap(next);
  };
  for (int it = 0; it < iterations; ++it) {
    step(lambda);
    step(mu);
  }
}

}  // namespace grainlab::ct
