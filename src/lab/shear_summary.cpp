// Peaks and final values of a direct shear series (definitions in shear_summary.h).
#include "lab/shear_summary.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace grainlab {

ShearSummary summarise_shear(const std::vector<std::vector<double>>& rows) {
  ShearSummary s;
  if (rows.size() < 2) return s;
  using C = ShearColumn;
  const double deg = 180 / std::numbers::pi;
  for (const auto& r : rows) {
    if (r[C::FrictionAngle] > s.peak_friction_angle_deg) {
      s.peak_friction_angle_deg = r[C::FrictionAngle];
      s.peak_stress_ratio = r[C::StressRatio];
      s.strain_at_peak_friction = r[C::Strain];
    }
  }
  // Dilation angle psi = atan(d(d_v)/d(d_h)) (Eq. 19), by central differences
  // over +-2 samples to tame the noise of single intervals.
  std::vector<double> psi(rows.size(), 0);
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const std::size_t lo = k >= 2 ? k - 2 : 0, hi = std::min(rows.size() - 1, k + 2);
    const double dh = rows[hi][C::HorizontalDisplacement] - rows[lo][C::HorizontalDisplacement];
    psi[k] = dh > 0 ? std::atan((rows[hi][C::VerticalDisplacement] - rows[lo][C::VerticalDisplacement]) / dh) * deg : 0;
    if (psi[k] > s.peak_dilation_angle_deg) {
      s.peak_dilation_angle_deg = psi[k];
      s.strain_at_peak_dilation = rows[k][C::Strain];
    }
  }
  const double last = rows.back()[C::Strain];
  int n = 0;
  for (std::size_t k = 0; k < rows.size(); ++k) {
    if (rows[k][C::Strain] < 0.9 * last) continue;
    s.final_friction_angle_deg += rows[k][C::FrictionAngle];
    s.final_dilation_angle_deg += psi[k];
    ++n;
  }
  if (n > 0) s.final_friction_angle_deg /= n, s.final_dilation_angle_deg /= n;
  s.final_void_ratio = rows.back()[C::VoidRatio];
  return s;
}

}  // namespace grainlab
