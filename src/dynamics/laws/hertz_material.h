// Hertz from material constants (Hertz-Mindlin with Tsuji-type damping).
//
// Parameters (Material): youngs_modulus E (Pa), poisson_ratio nu in (-1, 0.5),
// restitution e in (0, 1]. A pair mixes
//     1/E* = (1-nu_a^2)/E_a + (1-nu_b^2)/E_b,
//     1/G* = 2(2-nu_a)(1+nu_a)/E_a + 2(2-nu_b)(1+nu_b)/E_b,
// and beta from the mean restitution. With s = sqrt(R* delta), S_n = 2 E* s,
// S_t = 8 G* s:
//     K_n = (4/3) E* s, K_t = S_t, C_n = 2 sqrt(5/6) beta sqrt(S_n m*),
//     C_t = 2 sqrt(5/6) beta sqrt(S_t m*) = 2 sqrt(5/6) beta sqrt(4 G*/E*) sqrt(S_n m*),
// so a pair stores (PairCoefficients::c) E*, G*, beta and beta sqrt(4 G*/E*),
// and a contact takes one square root for both dampers.
// Elastic normal force f = (4/3) E* sqrt(R*) delta^{3/2}: tangent stiffness
// df/ddelta = (3/2) K_n = (3/2) f/delta, stored energy (2/5) f delta.
//
// Restitution. With this damping the restitution depends on beta alone (scale
// m*, R*, E* and the impact speed out of m* x'' = -(4/3)E* sqrt(R*) x^{3/2}
// - C_n x': x = L X, t = T tau with L^{1/2} T^2 E* sqrt(R*)/m* = 1 leaves
// X'' = -(4/3) X^{3/2} - 2 sqrt(5/6) beta sqrt(2) X^{1/4} X'). The usual
// formula beta = -ln e / sqrt(ln^2 e + pi^2) belongs to the linear spring and
// misses the requested e by several per cent for Hertz, so grainlab solves
// that dimensionless equation (with the no-tension clamp) once per
// restitution and inverts e(beta) by bisection: restitution_to_beta().
#pragma once

#include "dynamics/contact_law.h"

#include <array>
#include <cmath>

namespace grainlab {

// beta for the Hertz-material damping that gives restitution e exactly
// (see the derivation above). e in (0, 1]; e = 1 gives 0.
double restitution_to_beta(double e);
// The restitution the Hertz-material law gives for damping beta (solves the
// dimensionless impact equation with RK4); inverse of restitution_to_beta.
double hertz_restitution(double beta);

struct HertzMaterialLaw {
  static constexpr const char* name = "hertz-material";
  static constexpr const char* description = "Hertz-Mindlin from material constants";
  // E > 0, nu in (-1, 0.5), e in (0, 1].
  static constexpr std::array<LawParameter, 3> parameters{{
      {"youngs_modulus", "Pa", "Young's modulus", "> 0", law_rule::positive, 0, &Material::youngs_modulus},
      {"poisson_ratio", "", "Poisson ratio", "in (-1, 0.5)", [](double v) { return v > -1 && v < 0.5; }, 0,
       &Material::poisson_ratio},
      {"restitution", "", "coefficient of normal restitution", "in (0, 1]", [](double v) { return v > 0 && v <= 1; },
       0, &Material::restitution},
  }};
  // The slots of PairCoefficients::c: E*, G*, beta, beta sqrt(4 G*/E*).
  static constexpr int e_star = 0, g_star = 1, beta = 2, beta_t = 3, pair_slots = 4;

  // Harmonic E* and G*, beta from the mean restitution (gamma_t: beta sqrt(4 G*/E*)).
  static PairCoefficients mix(const Material& a, const Material& b);

  // K_n, C_n, K_t, C_t at overlap delta.
  template <typename T>
  static LawCoefficientsOf<T> at(const PairCoefficientsOf<T>& p, T delta, T r_eff, T m_eff) {
    constexpr double two_sqrt_5_6 = 1.8257418583505538;  // 2 sqrt(5/6)
    const T s = root(r_eff * delta);
    const T s_n = 2.0 * p.c[e_star] * s;
    const T s_t = 8.0 * p.c[g_star] * s;
    const T damper = two_sqrt_5_6 * root(s_n * m_eff);
    return {(2.0 / 3.0) * s_n, p.c[beta] * damper, s_t, p.c[beta_t] * damper};
  }

  // d f_n / d delta = (3/2) K_n.
  static double stiffness(const LawCoefficients& k) { return 1.5 * k.k_n; }
  // d f_n / d delta = (3/2) f / delta.
  static double tangent_stiffness(double f_n, double delta) { return 1.5 * f_n / delta; }
  // (2/5) f delta.
  static double elastic_energy(double f_n, double delta) { return 0.4 * f_n * delta; }
};

}  // namespace grainlab
