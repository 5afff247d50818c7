// The Mohr-Coulomb envelope over Mohr circles (definitions in mohr_coulomb.h).
#include "analysis/mohr_coulomb.h"

#include "core/error.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace grainlab::analysis {

double triaxial_sigma1(double sigma3, double eta) {
  if (!(sigma3 > 0) || !(eta >= 0 && eta < 3))
    input_error("a triaxial Mohr circle needs sigma_3 > 0 and 0 <= q/p' < 3, not sigma_3 = {} and q/p' = {}", sigma3,
                eta);
  return sigma3 * (3 + 2 * eta) / (3 - eta);
}

MohrCircle mohr_circle(double sigma1, double sigma3) { return {0.5 * (sigma1 + sigma3), 0.5 * (sigma1 - sigma3)}; }

MohrCoulombFit fit_mohr_coulomb(std::span<const MohrCircle> circles) {
  const std::size_t n = circles.size();
  if (n < 2)
    input_error("{} run{} with the stresses needed: a fit needs two or more", n, n == 1 ? "" : "s");
  double s_mean = 0, t_mean = 0, s_max = 0;
  for (const MohrCircle& c : circles) s_mean += c.s, t_mean += c.t, s_max = std::max(s_max, std::abs(c.s));
  s_mean /= n, t_mean /= n;
  double sxx = 0, sxt = 0, stt = 0;
  for (const MohrCircle& c : circles) {
    const double ds = c.s - s_mean, dt = c.t - t_mean;
    sxx += ds * ds, sxt += ds * dt, stt += dt * dt;
  }
  if (sxx <= (1e-9 * s_max) * (1e-9 * s_max))
    input_error("every circle has the same centre: give runs at different sigma_3");
  const double b = sxt / sxx, a = t_mean - b * s_mean;
  if (!(b > 0 && b < 1)) input_error("the best line has slope sin phi' = {:.3f}, outside (0, 1): no envelope", b);
  double ss_res = 0;
  for (const MohrCircle& c : circles) ss_res += (c.t - (a + b * c.s)) * (c.t - (a + b * c.s));
  const double phi = std::asin(b);
  MohrCoulombFit f;
  f.phi_deg = phi * 180 / std::numbers::pi;
  f.c = a / std::cos(phi);
  f.a = a;
  f.sin_phi = b;
  f.r_squared = stt > 0 ? 1 - ss_res / stt : 1.0;
  f.rms_residual = std::sqrt(ss_res / n);
  f.circles = static_cast<int>(n);
  return f;
}

}  // namespace grainlab::analysis
