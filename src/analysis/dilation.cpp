// Dilation angle series (definition in dilation.h).
#include "analysis/dilation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace grainlab::analysis {

std::vector<double> dilation_angle_series(std::span<const double> d_h, std::span<const double> d_v,
                                          int half_width) {
  if (d_h.size() != d_v.size()) throw std::invalid_argument("dilation_angle_series: d_h and d_v differ in length");
  if (half_width < 1) throw std::invalid_argument("dilation_angle_series: half_width must be at least 1");
  const std::size_t n = d_h.size(), h = static_cast<std::size_t>(half_width);
  std::vector<double> psi(n, std::numeric_limits<double>::quiet_NaN());
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t lo = k >= h ? k - h : 0, hi = std::min(n - 1, k + h);
    const double dh = d_h[hi] - d_h[lo];
    if (dh > 0) psi[k] = std::atan((d_v[hi] - d_v[lo]) / dh) * (180.0 / std::numbers::pi);
  }
  return psi;
}

}  // namespace grainlab::analysis
