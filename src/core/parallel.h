// Thin wrapper over OpenMP: the only file that spells pragmas or omp_* calls,
// so the threading policy lives in one place. Every parallel loop in grainlab
// writes only to slots owned by its own index (or reduces with an
// order-independent operation such as max), so results do not depend on the
// thread count. The thread count is passed per call (a World carries its own,
// WorldSettings::threads): nothing here changes process-wide state.
#pragma once

#include <omp.h>

#include <algorithm>
#include <cstddef>

namespace grainlab {

// Threads a parallel loop uses for a requested count (0 = the OpenMP default, all cores).
inline int resolve_threads(int requested) { return requested > 0 ? requested : omp_get_max_threads(); }

// Threads a loop with no explicit count uses (the OpenMP default).
inline int thread_count() { return omp_get_max_threads(); }

// Calls f(i) for i in [0, n) on `threads` threads (0 = default). Chunks are
// dynamic: loop bodies of uneven cost (narrowphase pairs) balance well; order
// of calls is unspecified. Loops of at most one chunk, or of fewer than
// min_parallel items, or given one thread, run serially (no OpenMP region):
// waking the threads costs tens of microseconds, more than a few thousand
// cheap items take.
template <typename F>
void parallel_for(std::ptrdiff_t n, F&& f, std::ptrdiff_t chunk = 64, int threads = 0,
                  std::ptrdiff_t min_parallel = 0) {
  const int t = resolve_threads(threads);
  if (n <= chunk || n < min_parallel || t == 1) {
    for (std::ptrdiff_t i = 0; i < n; ++i) f(i);
    return;
  }
#pragma omp parallel for schedule(dynamic, chunk) num_threads(t)
  for (std::ptrdiff_t i = 0; i < n; ++i) f(i);
}

// Calls f(i) for i in [0, n) and returns the maximum of what it returns (and
// of `init`), on `threads` threads (0 = default) when n > min_parallel, else
// serially. Static schedule; max is exact, so the result is thread-independent.
template <typename F>
double parallel_max(std::ptrdiff_t n, F&& f, double init, std::ptrdiff_t min_parallel, int threads = 0) {
  double m = init;
  const int t = resolve_threads(threads);
#pragma omp parallel for schedule(static) reduction(max : m) num_threads(t) if (n > min_parallel && t > 1)
  for (std::ptrdiff_t i = 0; i < n; ++i) m = std::max(m, f(i));
  return m;
}

}  // namespace grainlab
