// The trial-and-hold choice of a step's thread count (see thread_tuner.h).
#include "core/thread_tuner.h"

#include "core/parallel.h"

#include <fmt/format.h>

#include <algorithm>

namespace grainlab {

std::string thread_count_label(int threads) {
  if (threads > 0) return fmt::format("{} thread{}", threads, threads > 1 ? "s" : "");
  return fmt::format("up to {} threads (the fastest count, timed as it runs)", resolve_threads(0));
}

ThreadTuner::ThreadTuner(int max_threads, ThreadTuning timing) : timing_(timing) {
  for (int n = std::max(max_threads, 1);; n /= 2) {
    counts_.push_back(n);
    if (n == 1) break;
  }
  for (std::size_t c = 0; c < counts_.size(); ++c) order_.push_back(c);
  for (std::size_t c = counts_.size(); c-- > 0;) order_.push_back(c);
  steps_run_.assign(counts_.size(), 0);
  start_trial();
}

void ThreadTuner::start_trial() {
  seconds_.assign(counts_.size(), 0.0);
  steps_.assign(counts_.size(), 0);
  window_seconds_ = 0;
  window_steps_ = 0;
  held_seconds_ = 0;
  // One candidate: nothing to try.
  window_ = counts_.size() == 1 ? order_.size() : 0;
}

void ThreadTuner::record(double seconds) {
  ++steps_run_[holding() ? best_ : order_[window_]];
  window_seconds_ += seconds;
  ++window_steps_;
  const bool window_done = window_steps_ >= timing_.min_steps && window_seconds_ >= timing_.min_seconds;
  if (holding()) {
    held_seconds_ += seconds;
    if (counts_.size() == 1) return;
    if (held_seconds_ >= timing_.hold_seconds) return start_trial();
    if (!window_done) return;
    // A window of the held count: try again if its steps have become much
    // slower or faster than the trial measured (the step's cost or the
    // machine's load changed).
    const double ratio = window_seconds_ / window_steps_ / chosen_step_seconds_;
    window_seconds_ = 0;
    window_steps_ = 0;
    if (ratio > timing_.drift || ratio * timing_.drift < 1) start_trial();
    return;
  }
  if (!window_done) return;
  const std::size_t c = order_[window_];
  seconds_[c] += window_seconds_;
  steps_[c] += window_steps_;
  window_seconds_ = 0;
  window_steps_ = 0;
  if (++window_ < order_.size()) return;
  // Least time per step; on a tie, the count tried first (more threads).
  best_ = 0;
  for (std::size_t k = 1; k < counts_.size(); ++k)
    if (seconds_[k] * static_cast<double>(steps_[best_]) < seconds_[best_] * static_cast<double>(steps_[k]))
      best_ = k;
  chosen_step_seconds_ = seconds_[best_] / static_cast<double>(steps_[best_]);
  ++trials_;
  held_seconds_ = 0;
}

}  // namespace grainlab
