// Decompositions remembered for the life of the process: the same mesh with
// the same options gives the same pieces (decompose_convex is deterministic),
// so a process that builds the same grains several times (a run's index
// preparations and preparation-search trials, each of which places a fresh
// specimen; a resumed run) decomposes each shape once. A 200-face
// spherical-harmonic sand grain takes about 3 s to decompose (thousands of
// trial hulls), 24 shapes over a minute, against milliseconds to look up.
//
// Entries are matched on the mesh's exact bits and the options (a hash picks
// the candidates, an exact comparison decides), so a hit returns exactly
// what decompose_convex would. At most kDecompositionCacheEntries are kept;
// when full, the cache starts over (a process that cycles through more
// distinct grains than that only loses the saving). Thread-safe: shapes are
// decomposed in parallel.
#pragma once

#include "geometry/convex_decomposition.h"

#include <cstddef>

namespace grainlab {

inline constexpr std::size_t kDecompositionCacheEntries = 512;

// decompose_convex(mesh, options), computed once per distinct (mesh, options).
ConvexDecomposition decompose_convex_cached(const TriMesh& mesh, const DecompositionOptions& options = {});

// Counters of the cache, for tests and logs.
struct DecompositionCacheStats {
  std::size_t hits = 0, misses = 0, entries = 0;
};
DecompositionCacheStats decomposition_cache_stats();

// Forgets every entry and zeroes the counters.
void clear_decomposition_cache();

}  // namespace grainlab
