#include "ct/progress.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdio>

namespace grainlab::ct {

void Progress::start(const std::string& step) {
  step_ = step;
  clock_.reset();
  last_print_ = 0;
}

void Progress::report(double fraction) {
  if (!enabled_) return;
  const double t = clock_.seconds();
  if (t < 1.0 || t - last_print_ < 2.0) return;
  last_print_ = t;
  fraction = std::clamp(fraction, 0.0, 1.0);
  if (fraction <= 0) {
    fmt::print(stderr, "ct: {}: {:.0f} s so far\n", step_, t);
  } else {
    fmt::print(stderr, "ct: {}: {:.0f} %, about {:.0f} s to go\n", step_, 100 * fraction, t / fraction - t);
  }
  std::fflush(stderr);
}

void Progress::finish() {
  if (!enabled_) return;
  const double t = clock_.seconds();
  if (t >= 0.5) fmt::print(stderr, "ct: {}: done in {:.1f} s\n", step_, t);
}

}  // namespace grainlab::ct
