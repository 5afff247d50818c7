// Mixing and the restitution calibration of the Hertz-material
// law. Derivations are in hertz_material.h.
#include "dynamics/laws/hertz_material.h"

#include "core/error.h"

#include <cmath>
#include <map>
#include <mutex>

namespace grainlab {

PairCoefficients HertzMaterialLaw::mix(const Material& a, const Material& b) {
  const auto inv_e = [](const Material& m) { return (1 - m.poisson_ratio * m.poisson_ratio) / m.youngs_modulus; };
  const auto inv_g = [](const Material& m) {
    return 2 * (2 - m.poisson_ratio) * (1 + m.poisson_ratio) / m.youngs_modulus;
  };
  PairCoefficients p;
  p.c[e_star] = 1.0 / (inv_e(a) + inv_e(b));
  p.c[g_star] = 1.0 / (inv_g(a) + inv_g(b));
  p.c[beta] = restitution_to_beta(0.5 * (a.restitution + b.restitution));
  p.c[beta_t] = p.c[beta] * std::sqrt(4 * p.c[g_star] / p.c[e_star]);  // C_t's factor over sqrt(S_n m*) (hertz_material.h)
  return p;
}

// Solves X'' = -(4/3) X^{3/2} - 2 sqrt(5/3) beta X^{1/4} X' from X = 0, X' = 1
// until the (clamped) force stops pushing, and returns the rebound speed.
double hertz_restitution(double beta) {
  const double c = 2.0 * std::sqrt(5.0 / 3.0) * beta;
  const auto accel = [c](double x, double v) {
    if (x <= 0) return 0.0;
    return std::min(0.0, -(4.0 / 3.0) * std::pow(x, 1.5) - c * std::pow(x, 0.25) * v);
  };
  const double h = 2e-4;  // e converges as h^2 near the X^{1/4} start: 1e-6 at this step
  double x = 0, v = 1;
  for (int i = 0; i < 10'000'000; ++i) {
    const double k1x = v, k1v = accel(x, v);
    const double k2x = v + 0.5 * h * k1v, k2v = accel(x + 0.5 * h * k1x, v + 0.5 * h * k1v);
    const double k3x = v + 0.5 * h * k2v, k3v = accel(x + 0.5 * h * k2x, v + 0.5 * h * k2v);
    const double k4x = v + h * k3v, k4v = accel(x + h * k3x, v + h * k3v);
    x += h / 6 * (k1x + 2 * k2x + 2 * k3x + k4x);
    v += h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
    if (v < 0 && (x <= 0 || accel(x, v) >= 0)) return -v;
  }
  return 0;  // never separated (critically damped)
}

double restitution_to_beta(double e) {
  if (!(e > 0 && e <= 1)) input_error("restitution {} is outside (0, 1]", e);
  if (e >= 1) return 0;
  static std::mutex mutex;
  static std::map<double, double> cache;
  std::lock_guard lock(mutex);
  if (auto it = cache.find(e); it != cache.end()) return it->second;
  // e(beta) falls monotonically from 1 at beta = 0.
  double lo = 0, hi = 1;
  while (hertz_restitution(hi) > e) hi *= 2;
  for (int i = 0; i < 48; ++i) {
    const double mid = 0.5 * (lo + hi);
    (hertz_restitution(mid) > e ? lo : hi) = mid;
  }
  return cache[e] = 0.5 * (lo + hi);
}

}  // namespace grainlab
