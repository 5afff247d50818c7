// Hooke: the linear spring-dashpot.
//
// Parameters (Material): k_n, k_t (N/m), gamma_n, gamma_t (1/s); pairs mix
// them by the mean. Coefficients at any overlap:
//     K_n = k_n, C_n = gamma_n m*, K_t = k_t, C_t = gamma_t m*.
// Elastic normal force f = k_n delta: tangent stiffness df/ddelta = k_n = f/delta,
// stored energy int_0^delta k_n x dx = (1/2) f delta.
// An undamped head-on impact lasts pi sqrt(m*/k_n); with damping the contact
// is the oscillator m* x'' + gamma_n m* x' + k_n x = 0 (restitution in
// tests/dynamics/hooke_impact_test.cpp).
#pragma once

#include "dynamics/contact_law.h"
#include "dynamics/laws/user_coefficients.h"

#include <cmath>

namespace grainlab {

struct HookeLaw {
  static constexpr const char* name = "hooke";
  static constexpr const char* description = "linear spring-dashpot";
  static constexpr auto parameters = user_coefficient_parameters("N/m", "1/s");
  static constexpr int pair_slots = UserSlots::count;

  // The mean of each user coefficient.
  static PairCoefficients mix(const Material& a, const Material& b) { return mix_user_coefficients(a, b); }

  // K_n, C_n, K_t, C_t (independent of the overlap).
  template <typename T>
  static LawCoefficientsOf<T> at(const PairCoefficientsOf<T>& p, T /*delta*/, T /*r_eff*/, T m_eff) {
    using S = UserSlots;
    return {p.c[S::k_n], p.c[S::gamma_n] * m_eff, p.c[S::k_t], p.c[S::gamma_t] * m_eff};
  }

  // d f_n / d delta = K_n.
  static double stiffness(const LawCoefficients& k) { return k.k_n; }
  // d f_n / d delta = f / delta.
  static double tangent_stiffness(double f_n, double delta) { return f_n / delta; }
  // (1/2) f delta.
  static double elastic_energy(double f_n, double delta) { return 0.5 * f_n * delta; }
};

}  // namespace grainlab
