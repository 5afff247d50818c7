// ThreadTuner: how many threads a World's step uses when its settings leave
// the count to grainlab (WorldSettings::threads = 0, numerics.threads = 0).
//
// Why measure instead of taking every core: a step is about eight parallel
// loops, and each one hands work to the other threads and waits for them.
// On this project's 2-core machine (a VM) that hand-over costs more than a
// cheap world's loops save: the 2000-bead direct shear (bench_sphere_lab,
// 2026-12-04, alternated twice) sheared at 3.91 / 4.24e6 particle-steps/s on
// one thread and 2.81 / 2.89e6 on two; every phase was slower on two
// (narrowphase 0.20 -> 0.33 ms/step, integrate 0.05 -> 0.10, though the
// integration runs serially there: the bodies' data now lives in the other
// core's cache half the time). Faceted grains are the other way round (the
// settled bed of 2000-face hulls: 122,000 grain-steps/s on one thread,
// 192,000 on two), and which count wins also depends on what else the
// machine is running. Results do not depend on the count (world.cpp), so it
// can be chosen by the clock alone.
//
// How: the candidates are max, max/2, max/4, ..., 1 threads. A trial runs
// each for one window (at least `min_steps` steps and `min_seconds` of step
// time) in the order c0, c1, ..., ck, then once more in the reverse order,
// so that a step cost that drifts steadily during the trial (grains coming
// to rest, a packing densifying) weighs on every candidate alike; it keeps
// the candidate of least step time per step and holds it, timing it in
// windows of the same size, until a window's steps are `drift` times slower
// or faster than in the trial, or for `hold_seconds` of step time at most;
// then it tries again. The cost of a step changes (a deposition's grains
// land: the demo's step slows 5-fold in its first 30 s) and so does the
// machine's load. A trial takes four windows (0.4 s); a steady run tries
// again every 30 s, spending about 1 % of its time on the slower counts.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace grainlab {

// How a run states its thread count `threads` (WorldSettings::threads):
// "2 threads", or for 0 "up to N threads (the fastest count, timed as it runs)".
std::string thread_count_label(int threads);

// The tuner's windows (see above).
struct ThreadTuning {
  double min_seconds = 0.1;  // step time of one window (s)
  int min_steps = 10;        // steps of one window
  double hold_seconds = 30;  // step time the chosen count runs before the next trial (s)
  double drift = 1.3;        // or until a window of it is this factor slower or faster than in the trial
};

class ThreadTuner {
 public:
  ThreadTuner() : ThreadTuner(1) {}
  explicit ThreadTuner(int max_threads, ThreadTuning timing = {});

  // The thread count for the next step.
  int threads() const { return holding() ? counts_[best_] : counts_[order_[window_]]; }
  // The step just run with threads() took `seconds`.
  void record(double seconds);

  int max_threads() const { return counts_.front(); }
  // Trials finished so far; the count the last one chose.
  std::int64_t trials() const { return trials_; }
  int chosen() const { return counts_[best_]; }
  // The candidate counts (most first) and the steps run on each so far.
  const std::vector<int>& counts() const { return counts_; }
  const std::vector<std::int64_t>& steps_run() const { return steps_run_; }

 private:
  bool holding() const { return window_ == order_.size(); }
  void start_trial();

  ThreadTuning timing_;
  std::vector<int> counts_;      // candidates, most threads first
  std::vector<std::size_t> order_;  // the trial's windows: candidate indices
  std::vector<double> seconds_;  // per candidate, over this trial's windows
  std::vector<std::int64_t> steps_;
  std::vector<std::int64_t> steps_run_;  // per candidate, the whole run
  std::size_t window_ = 0;  // position in order_; order_.size() while holding
  double window_seconds_ = 0;
  int window_steps_ = 0;
  double held_seconds_ = 0;
  double chosen_step_seconds_ = 0;  // the chosen count's step time in the trial (s)
  std::size_t best_ = 0;
  std::int64_t trials_ = 0;
};

}  // namespace grainlab
