// Material mixing and the restitution calibration of the Hertz-material law.
// Derivations are in material.h.
#include "dynamics/material.h"

#include "core/error.h"

#include <cmath>
#include <map>
#include <mutex>

namespace grainlab {

ContactLaw parse_contact_law(const std::string& name) {
  if (name == "hooke") return ContactLaw::Hooke;
  if (name == "hertz") return ContactLaw::HertzUser;
  if (name == "hertz-material") return ContactLaw::HertzMaterial;
  input_error("unknown contact law '{}': use \"hertz\" (the paper's user coefficients k_n, k_t, "
              "gamma_n, gamma_t), \"hertz-material\" (Young's modulus, Poisson ratio, restitution) "
              "or \"hooke\" (linear spring-dashpot)",
              name);
}

const char* contact_law_name(ContactLaw law) {
  switch (law) {
    case ContactLaw::Hooke: return "hooke";
    case ContactLaw::HertzUser: return "hertz";
    case ContactLaw::HertzMaterial: return "hertz-material";
  }
  return "?";
}

PairCoefficients mix(const Material& a, const Material& b, ContactLaw law) {
  PairCoefficients p;
  p.friction = std::min(a.friction, b.friction);
  if (law == ContactLaw::HertzMaterial) {
    const auto inv_e = [](const Material& m) {
      return (1 - m.poisson_ratio * m.poisson_ratio) / m.youngs_modulus;
    };
    const auto inv_g = [](const Material& m) {
      return 2 * (2 - m.poisson_ratio) * (1 + m.poisson_ratio) / m.youngs_modulus;
    };
    p.k_n = 1.0 / (inv_e(a) + inv_e(b));  // E*
    p.k_t = 1.0 / (inv_g(a) + inv_g(b));  // G*
    p.gamma_n = p.gamma_t = restitution_to_beta(0.5 * (a.restitution + b.restitution));
  } else {
    p.k_n = 0.5 * (a.k_n + b.k_n);
    p.k_t = 0.5 * (a.k_t + b.k_t);
    p.gamma_n = 0.5 * (a.gamma_n + b.gamma_n);
    p.gamma_t = 0.5 * (a.gamma_t + b.gamma_t);
  }
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

void validate(const Material& m, ContactLaw law) {
  const auto need = [&](bool ok, const char* field, double value, const char* rule) {
    if (!ok) input_error("material '{}': {} = {} is impossible; it must be {}", m.name, field, value, rule);
  };
  need(m.density > 0 && std::isfinite(m.density), "density", m.density, "> 0 (kg/m^3)");
  need(m.friction >= 0 && std::isfinite(m.friction), "friction", m.friction, ">= 0");
  if (law == ContactLaw::HertzMaterial) {
    need(m.youngs_modulus > 0 && std::isfinite(m.youngs_modulus), "youngs_modulus", m.youngs_modulus, "> 0 (Pa)");
    need(m.poisson_ratio > -1 && m.poisson_ratio < 0.5, "poisson_ratio", m.poisson_ratio, "in (-1, 0.5)");
    need(m.restitution > 0 && m.restitution <= 1, "restitution", m.restitution, "in (0, 1]");
  } else {
    need(m.k_n > 0 && std::isfinite(m.k_n), "k_n", m.k_n, "> 0");
    need(m.k_t >= 0 && std::isfinite(m.k_t), "k_t", m.k_t, ">= 0");
    need(m.gamma_n >= 0 && std::isfinite(m.gamma_n), "gamma_n", m.gamma_n, ">= 0");
    need(m.gamma_t >= 0 && std::isfinite(m.gamma_t), "gamma_t", m.gamma_t, ">= 0");
  }
}

}  // namespace grainlab
