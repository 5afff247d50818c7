// Hertz with user coefficients (the paper's Eqs. 7-8).
//
// Parameters (Material): k_n, k_t (N/m^2; the paper's Table 1 writes N/m),
// gamma_n, gamma_t (1/(m s)); pairs mix them by the mean. With
// s = sqrt(R* delta):
//     K_n = k_n s, C_n = gamma_n m* s, K_t = k_t s, C_t = gamma_t m* s.
// The paper typesets the factor as sqrt(R*) delta; that is not a force (the
// units do not work): sqrt(R* delta) is the form whose units are newtons.
// Elastic normal force f = k_n sqrt(R*) delta^{3/2}: tangent stiffness
// df/ddelta = (3/2) K_n = (3/2) f/delta, stored energy
// int_0^delta f dx = (2/5) f delta.
#pragma once

#include "dynamics/contact_law.h"
#include "dynamics/laws/user_coefficients.h"

#include <cmath>

namespace grainlab {

struct HertzUserLaw {
  static constexpr const char* name = "hertz";
  static constexpr const char* description = "Hertz with the paper's user coefficients";
  static constexpr auto parameters = user_coefficient_parameters("N/m^2", "1/(m s)");
  static constexpr int pair_slots = UserSlots::count;

  // The mean of each user coefficient.
  static PairCoefficients mix(const Material& a, const Material& b) { return mix_user_coefficients(a, b); }

  // K_n, C_n, K_t, C_t at overlap delta.
  template <typename T>
  static LawCoefficientsOf<T> at(const PairCoefficientsOf<T>& p, T delta, T r_eff, T m_eff) {
    const T s = root(r_eff * delta);
    using S = UserSlots;
    return {p.c[S::k_n] * s, p.c[S::gamma_n] * m_eff * s, p.c[S::k_t] * s, p.c[S::gamma_t] * m_eff * s};
  }

  // d f_n / d delta = (3/2) K_n.
  static double stiffness(const LawCoefficients& k) { return 1.5 * k.k_n; }
  // d f_n / d delta = (3/2) f / delta.
  static double tangent_stiffness(double f_n, double delta) { return 1.5 * f_n / delta; }
  // (2/5) f delta.
  static double elastic_energy(double f_n, double delta) { return 0.4 * f_n * delta; }
};

}  // namespace grainlab
