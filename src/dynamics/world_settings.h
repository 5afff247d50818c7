// The knobs of a World that are neither Model (physics) nor State (what
// changes): the Verlet skin, the overlap the critical step is sized for, and
// the World's own thread count (never a process-wide setting).
#pragma once

#include "core/thread_tuner.h"

#include <cstddef>

namespace grainlab {

struct WorldSettings {
  // Verlet skin (m): candidate pairs are kept while no grain has moved more
  // than skin/2 since the last broadphase. 0 = automatic, set at the first
  // step to 0.2 x the smallest grain's volume-equivalent radius.
  double skin = 0;
  // Reference overlap for the critical time step, as a fraction of the
  // smallest grain's equivalent radius (overlaps larger than this are not
  // expected in a well-posed run).
  double expected_overlap_fraction = 0.01;
  // Threads of every parallel loop of this World's step; 0 = automatic: up
  // to all cores (the OpenMP default), the count whose steps run fastest,
  // timed as the run goes (core/thread_tuner.h; `thread_tuning` sets its
  // windows). Results do not depend on it.
  int threads = 0;
  ThreadTuning thread_tuning;
  // Loops of cheap items (contact forces, bounds, and integration and every
  // per-pair loop when all grains are spheres) run serially below this many
  // items: waking a second thread costs tens of microseconds per loop, and
  // a step has about eight loops. Measured on 510 glass beads (the triaxial
  // test's 8 d_max box), 2 threads took 23.3 s against 12.7 s for one
  // without it, 11.0 s with it; sub-angular grains' steps are unchanged.
  // Results do not depend on it (tests set 0 to run every parallel branch).
  std::ptrdiff_t serial_below = 4096;
};

}  // namespace grainlab
