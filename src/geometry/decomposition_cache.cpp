// The process-wide cache of convex decompositions (see decomposition_cache.h).
#include "geometry/decomposition_cache.h"

#include <cstdint>
#include <cstring>
#include <mutex>
#include <unordered_map>
#include <vector>

namespace grainlab {

namespace {

struct Entry {
  TriMesh mesh;
  DecompositionOptions options;
  ConvexDecomposition result;
};

struct Cache {
  std::mutex mutex;
  std::unordered_multimap<std::uint64_t, Entry> entries;
  DecompositionCacheStats stats;
};

Cache& cache() {
  static Cache c;
  return c;
}

// FNV-1a over raw bytes.
void mix(std::uint64_t& h, const void* data, std::size_t n) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < n; ++i) h = (h ^ p[i]) * 1099511628211ull;
}

std::uint64_t key_of(const TriMesh& mesh, const DecompositionOptions& o) {
  std::uint64_t h = 14695981039346656037ull;
  mix(h, mesh.vertices.data(), mesh.vertices.size() * sizeof(Vec3));
  mix(h, mesh.faces.data(), mesh.faces.size() * sizeof(Face));
  mix(h, &o.max_pieces, sizeof o.max_pieces);
  mix(h, &o.tolerance, sizeof o.tolerance);
  mix(h, &o.grid, sizeof o.grid);
  return h;
}

template <class T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

bool same_input(const Entry& e, const TriMesh& mesh, const DecompositionOptions& o) {
  return same_bits(e.mesh.vertices, mesh.vertices) && same_bits(e.mesh.faces, mesh.faces) &&
         e.options.max_pieces == o.max_pieces && std::memcmp(&e.options.tolerance, &o.tolerance, sizeof o.tolerance) == 0 &&
         e.options.grid == o.grid;
}

}  // namespace

ConvexDecomposition decompose_convex_cached(const TriMesh& mesh, const DecompositionOptions& options) {
  Cache& c = cache();
  const std::uint64_t key = key_of(mesh, options);
  {
    const std::lock_guard lock(c.mutex);
    const auto [first, last] = c.entries.equal_range(key);
    for (auto it = first; it != last; ++it)
      if (same_input(it->second, mesh, options)) {
        ++c.stats.hits;
        return it->second.result;
      }
  }
  // Decomposed outside the lock (shapes are decomposed in parallel); two
  // threads given the same new mesh at once both compute the same result.
  ConvexDecomposition result = decompose_convex(mesh, options);
  const std::lock_guard lock(c.mutex);
  ++c.stats.misses;
  if (c.entries.size() >= kDecompositionCacheEntries) c.entries.clear();
  c.entries.emplace(key, Entry{mesh, options, result});
  return result;
}

DecompositionCacheStats decomposition_cache_stats() {
  Cache& c = cache();
  const std::lock_guard lock(c.mutex);
  DecompositionCacheStats s = c.stats;
  s.entries = c.entries.size();
  return s;
}

void clear_decomposition_cache() {
  Cache& c = cache();
  const std::lock_guard lock(c.mutex);
  c.entries.clear();
  c.stats = {};
}

}  // namespace grainlab
