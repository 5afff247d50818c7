// The knobs of a World that are neither Model (physics) nor State (what
// changes): the Verlet skin, the overlap the critical step is sized for, and
// the World's own thread count (never a process-wide setting).
#pragma once

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
  // Threads of every parallel loop of this World's step (0 = the OpenMP
  // default, all cores). Results do not depend on it.
  int threads = 0;
};

}  // namespace grainlab
