#include "ct/otsu.h"

#include <algorithm>
#include <vector>

namespace grainlab::ct {

OtsuResult otsu_threshold(std::span<const float> values, int bins) {
  const auto [lo_it, hi_it] = std::minmax_element(values.begin(), values.end());
  const double lo = *lo_it, hi = *hi_it;
  const double width = (hi - lo) / bins;
  std::vector<double> count(bins, 0.0);
  for (float v : values) count[std::min(bins - 1, static_cast<int>((v - lo) / width))] += 1;
  const double n = static_cast<double>(values.size());
  double total_mean = 0;
  for (int b = 0; b < bins; ++b) total_mean += count[b] / n * (lo + (b + 0.5) * width);
  double w0 = 0, m = 0, best = -1;
  int best_bin = 0;
  for (int b = 0; b < bins - 1; ++b) {
    w0 += count[b] / n;
    m += count[b] / n * (lo + (b + 0.5) * width);
    if (w0 <= 0 || w0 >= 1) continue;
    const double d = total_mean * w0 - m;
    const double s = d * d / (w0 * (1 - w0));
    if (s > best) {
      best = s;
      best_bin = b;
    }
  }
  return class_means(values, static_cast<float>(lo + (best_bin + 1) * width));
}

OtsuResult class_means(std::span<const float> values, float threshold) {
  double s0 = 0, s1 = 0, n0 = 0, n1 = 0;
  for (float v : values) {
    if (v > threshold) {
      s1 += v;
      n1 += 1;
    } else {
      s0 += v;
      n0 += 1;
    }
  }
  return {threshold, n0 > 0 ? s0 / n0 : threshold, n1 > 0 ? s1 / n1 : threshold};
}

}  // namespace grainlab::ct
