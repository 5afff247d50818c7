// The user-coefficient laws' shared parameters: k_n, k_t, gamma_n, gamma_t,
// given per material (units set by the law) and mixed by the mean.
#pragma once

#include "dynamics/contact_law.h"

#include <cmath>

namespace grainlab {

// k_n > 0, k_t, gamma_n, gamma_t >= 0, all finite.
inline void validate_user_coefficients(const Material& m) {
  require_material_field(m, m.k_n > 0 && std::isfinite(m.k_n), "k_n", m.k_n, "> 0");
  require_material_field(m, m.k_t >= 0 && std::isfinite(m.k_t), "k_t", m.k_t, ">= 0");
  require_material_field(m, m.gamma_n >= 0 && std::isfinite(m.gamma_n), "gamma_n", m.gamma_n, ">= 0");
  require_material_field(m, m.gamma_t >= 0 && std::isfinite(m.gamma_t), "gamma_t", m.gamma_t, ">= 0");
}

// The mean of each user coefficient.
inline PairCoefficients mix_user_coefficients(const Material& a, const Material& b) {
  PairCoefficients p;
  p.k_n = 0.5 * (a.k_n + b.k_n);
  p.k_t = 0.5 * (a.k_t + b.k_t);
  p.gamma_n = 0.5 * (a.gamma_n + b.gamma_n);
  p.gamma_t = 0.5 * (a.gamma_t + b.gamma_t);
  return p;
}

}  // namespace grainlab
