// The OpenMP wait policy grainlab runs with: idle threads sleep (PASSIVE)
// unless the user says otherwise.
//
// libgomp's default lets a thread that reaches a barrier spin for a while
// before it sleeps. On a machine that is not shared that is fastest, but a
// DEM step has several parallel loops, and when another CPU-bound process
// holds a core, the spinning threads burn the time slices the descheduled
// thread needs, and every barrier waits for it. Measured (2026-11-30, this
// 2-core machine, alternating the three settings: bench_scenes --only spheres
// --grains 2000 --settle 1000 --steps 1500, 2 threads, grain-steps/s, two
// runs each; "loaded" = one busy-loop shell process beside it):
//                     quiet                loaded
//   default           1.19e6, 1.97e6       0.53e6, 0.63e6
//   GOMP_SPINCOUNT=1e4 2.08e6, 1.75e6      0.47e6, 0.36e6
//   PASSIVE           1.90e6, 1.51e6       0.98e6, 0.96e6
// PASSIVE keeps about 55 % of the quiet speed under load (the default about
// 35 %), and its quiet cost is within this machine's noise. The demo
// (`grainlab run --default`, progress rate over its first 40 s, steps/s):
// alone 141-148 PASSIVE, 136-140 spinning (GOMP_SPINCOUNT=300000, libgomp's
// default); beside a busy loop 88-97 vs 73-82; two demos at once 84-89 each
// vs 25-28 each.
//
// libgomp reads OMP_WAIT_POLICY once, when it is loaded (before main), so
// the default can only be set by running the program again with the
// variable set: use_passive_wait_by_default() re-executes /proc/self/exe
// when neither OMP_WAIT_POLICY nor GOMP_SPINCOUNT is in the environment
// (the user's setting always wins), and returns if that is not possible.
#pragma once

#include <cstdlib>
#include <unistd.h>

namespace grainlab {

// Call first in main(), before any OpenMP region has run.
inline void use_passive_wait_by_default(char** argv) {
  if (std::getenv("OMP_WAIT_POLICY") || std::getenv("GOMP_SPINCOUNT")) return;
  if (setenv("OMP_WAIT_POLICY", "PASSIVE", 1) != 0) return;
  execv("/proc/self/exe", argv);
  // exec failed (no /proc): carry on with the default policy; the variable
  // set above only affects child processes.
}

}  // namespace grainlab
