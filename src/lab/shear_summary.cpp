// Peaks and final values of a direct shear series (definitions in shear_summary.h).
#include "lab/shear_summary.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace grainlab {

ShearSummary summarise_shear(const std::vector<std::vector<double>>& rows) {
  ShearSummary s;
  if (rows.size() < 2) return s;
  constexpr int kStrain = 1, kDh = 2, kDv = 3, kRatio = 7, kPhi = 8, kE = 9;
  const double deg = 180 / std::numbers::pi;
  for (const auto& r : rows) {
    if (r[kPhi] > s.peak_friction_angle_deg) {
      s.peak_friction_angle_deg = r[kPhi];
      s.peak_stress_ratio = r[kRatio];
      s.strain_at_peak_friction = r[kStrain];
    }
  }
  // Dilation angle psi = atan(d(d_v)/d(d_h)) (Eq. 19), by central differences
  // over +-2 samples to tame the noise of single intervals.
  std::vector<double> psi(rows.size(), 0);
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const std::size_t lo = k >= 2 ? k - 2 : 0, hi = std::min(rows.size() - 1, k + 2);
    const double dh = rows[hi][kDh] - rows[lo][kDh];
    psi[k] = dh > 0 ? std::atan((rows[hi][kDv] - rows[lo][kDv]) / dh) * deg : 0;
    if (psi[k] > s.peak_dilation_angle_deg) {
      s.peak_dilation_angle_deg = psi[k];
      s.strain_at_peak_dilation = rows[k][kStrain];
    }
  }
  const double last = rows.back()[kStrain];
  int n = 0;
  for (std::size_t k = 0; k < rows.size(); ++k) {
    if (rows[k][kStrain] < 0.9 * last) continue;
    s.final_friction_angle_deg += rows[k][kPhi];
    s.final_dilation_angle_deg += psi[k];
    ++n;
  }
  if (n > 0) s.final_friction_angle_deg /= n, s.final_dilation_angle_deg /= n;
  s.final_void_ratio = rows.back()[kE];
  return s;
}

}  // namespace grainlab
