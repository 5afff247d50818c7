// Progress of the long steps of a CT segmentation, with an estimated time to
// go, on standard error. Silent when disabled (tests, --quiet).
#pragma once

#include "core/timer.h"

#include <string>

namespace grainlab::ct {

class Progress {
 public:
  explicit Progress(bool enabled) : enabled_(enabled) {}

  // Starts a named step ("distance map", "meshing grains").
  void start(const std::string& step);
  // The current step is this fraction (0-1) done: prints the percentage and an
  // ETA (elapsed / fraction - elapsed), at most every 2 s, once the step has
  // run for 1 s.
  void report(double fraction);
  // Ends the current step and prints its time when it took 0.5 s or more.
  void finish();
  bool enabled() const { return enabled_; }

 private:
  bool enabled_;
  std::string step_;
  Stopwatch clock_;
  double last_print_ = 0;
};

}  // namespace grainlab::ct
