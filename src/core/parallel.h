// Thin wrapper over OpenMP so that the rest of the code never spells pragmas
// with varying schedules. Every parallel loop in grainlab writes only to slots
// owned by its own index, so results do not depend on the thread count.
#pragma once

#include <omp.h>

#include <cstddef>

namespace grainlab {

// Sets the number of threads used by parallel_for (0 = OpenMP default).
inline void set_thread_count(int n) {
  if (n > 0) omp_set_num_threads(n);
}

inline int thread_count() { return omp_get_max_threads(); }

// Calls f(i) for i in [0, n). Chunks are dynamic: loop bodies of uneven cost
// (narrowphase pairs) balance well; order of calls is unspecified.
template <typename F>
void parallel_for(std::ptrdiff_t n, F&& f, std::ptrdiff_t chunk = 64) {
  if (n <= chunk) {
    for (std::ptrdiff_t i = 0; i < n; ++i) f(i);
    return;
  }
#pragma omp parallel for schedule(dynamic, chunk)
  for (std::ptrdiff_t i = 0; i < n; ++i) f(i);
}

}  // namespace grainlab
