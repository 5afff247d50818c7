// Peaks of a recorded curve and the peak rule (definitions in peak.h).
#include "analysis/peak.h"

#include <algorithm>
#include <cmath>

namespace grainlab::analysis {

bool is_peak_at(double at, double end) { return at < (1 - kPeakEndFraction) * end; }

std::optional<double> series_peak(std::span<const double> values) {
  std::optional<double> peak;
  for (double v : values)
    if (std::isfinite(v) && (!peak || v > *peak)) peak = v;
  return peak;
}

std::optional<CurvePeak> curve_peak(std::span<const double> values, std::span<const double> progress) {
  const std::size_t n = std::min(values.size(), progress.size());
  std::optional<CurvePeak> peak;
  double end = -INFINITY;
  for (std::size_t k = 0; k < n; ++k) {
    if (std::isfinite(progress[k])) end = std::max(end, progress[k]);
    if (!std::isfinite(values[k]) || !std::isfinite(progress[k])) continue;
    if (!peak || values[k] > peak->value) peak = CurvePeak{values[k], progress[k], k, false};
  }
  if (peak) peak->is_peak = is_peak_at(peak->at, end);
  return peak;
}

}  // namespace grainlab::analysis
