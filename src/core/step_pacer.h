// How many steps to take before looking again at a stop request: as many as
// run in about `period_s` of wall-clock time (measured on the chunks before),
// between 1 and `max_steps`. A stop signal is then honoured within a fraction
// of a second at any speed (a 2000-grain bed steps some 15 times a second,
// 1000 beads thousands), while fast runs still check rarely. The chunk
// changes only where a loop pauses, never what the steps compute: every
// protocol's advance(n) decides by step counts, so resume stays bit-identical.
// A period of infinity keeps every chunk at `max_steps` (after the first):
// tests that stop a loop at a given step use it.
#pragma once

#include "core/timer.h"

#include <algorithm>
#include <cstdint>

namespace grainlab {

class StepPacer {
 public:
  // `first_steps`: the first chunk, before any speed is measured.
  explicit StepPacer(int max_steps = 200, double period_s = 0.25, int first_steps = 1)
      : max_(max_steps), period_(period_s), chunk_(first_steps) {}

  // Steps for the next chunk; call done() after it with the steps it took.
  int next() {
    clock_.reset();
    return chunk_;
  }
  void done(std::int64_t steps) {
    const double s = clock_.seconds();
    if (steps <= 0 || s <= 0) return;
    chunk_ = static_cast<int>(std::clamp(static_cast<double>(steps) / s * period_, 1.0, static_cast<double>(max_)));
  }

 private:
  int max_;
  double period_;
  int chunk_;
  Stopwatch clock_;
};

}  // namespace grainlab
