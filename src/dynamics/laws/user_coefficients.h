// The user-coefficient laws' shared parameters: k_n, k_t, gamma_n, gamma_t,
// given per material (units set by the law) and mixed by the mean:
//     k_n = (k_n,a + k_n,b)/2, and the same for k_t, gamma_n, gamma_t.
// Hooke and Hertz declare the same keys, so they share the values (the flat
// config keys k_n, ... serve both).
#pragma once

#include "dynamics/contact_law.h"

#include <array>

namespace grainlab {

// The slots of PairCoefficients::c that the user-coefficient laws fill.
struct UserSlots {
  static constexpr int k_n = 0, k_t = 1, gamma_n = 2, gamma_t = 3, count = 4;
};

// k_n > 0; k_t, gamma_n, gamma_t >= 0. Units: k_unit for the stiffnesses,
// gamma_unit for the dampings.
constexpr std::array<LawParameter, 4> user_coefficient_parameters(const char* k_unit, const char* gamma_unit) {
  return {{
      {"k_n", k_unit, "normal stiffness", "> 0", law_rule::positive, 0, &Material::k_n},
      {"k_t", k_unit, "tangential stiffness", ">= 0", law_rule::non_negative, 0, &Material::k_t},
      {"gamma_n", gamma_unit, "normal damping", ">= 0", law_rule::non_negative, 0, &Material::gamma_n},
      {"gamma_t", gamma_unit, "tangential damping", ">= 0", law_rule::non_negative, 0, &Material::gamma_t},
  }};
}

// The mean of each user coefficient.
inline PairCoefficients mix_user_coefficients(const Material& a, const Material& b) {
  PairCoefficients p;
  p.c[UserSlots::k_n] = 0.5 * (a.k_n + b.k_n);
  p.c[UserSlots::k_t] = 0.5 * (a.k_t + b.k_t);
  p.c[UserSlots::gamma_n] = 0.5 * (a.gamma_n + b.gamma_n);
  p.c[UserSlots::gamma_t] = 0.5 * (a.gamma_t + b.gamma_t);
  return p;
}

}  // namespace grainlab
