// Materials and the contact laws that turn an overlap into a force.
//
// Symbols (paper section 2.2, DESIGN.md "Contact physics"): overlap delta (m),
// unit normal n from body a to body b, effective mass m* = m_a m_b/(m_a+m_b),
// effective radius R* = R_a R_b/(R_a+R_b), normal relative velocity
// v_n = (v_b - v_a).n (negative while approaching), tangential part v_t.
//
// Every law is reduced, at the current overlap, to four coefficients
//     f_n = K_n delta - C_n v_n          (clamped at 0: no tension)
//     f_t = -K_t xi   - C_t v_t          (capped by Coulomb, mu f_n)
// where xi is the tangential spring (m). The laws:
//
//  * Hooke (linear):   K_n = k_n, C_n = gamma_n m*, K_t = k_t, C_t = gamma_t m*.
//    k in N/m, gamma in 1/s.
//  * Hertz, user coefficients (the paper's Eqs. 7-8 with the typeset error
//    fixed: the factor is sqrt(R* delta), not sqrt(R*) delta, or the units
//    would not be newtons):  s = sqrt(R* delta),
//    K_n = k_n s, C_n = gamma_n m* s, K_t = k_t s, C_t = gamma_t m* s.
//    k in N/m^2 (the paper's Table 1 writes N/m), gamma in 1/(m s).
//  * Hertz, material (Hertz-Mindlin with Tsuji-type damping):
//    1/E* = (1-nu_a^2)/E_a + (1-nu_b^2)/E_b,
//    1/G* = 2(2-nu_a)(1+nu_a)/E_a + 2(2-nu_b)(1+nu_b)/E_b,
//    s = sqrt(R* delta), S_n = 2 E* s, S_t = 8 G* s,
//    K_n = (4/3) E* s, K_t = S_t, C_n = 2 sqrt(5/6) beta sqrt(S_n m*),
//    C_t = 2 sqrt(5/6) beta sqrt(S_t m*).
//    With this damping the restitution depends on beta alone (scale m*, R*,
//    E* and the impact speed out of m* x'' = -(4/3)E* sqrt(R*) x^{3/2}
//    - C_n x': x = L X, t = T tau with L^{1/2} T^2 E* sqrt(R*)/m* = 1 leaves
//    X'' = -(4/3) X^{3/2} - 2 sqrt(5/6) beta sqrt(2) X^{1/4} X'). The usual
//    formula beta = -ln e / sqrt(ln^2 e + pi^2) belongs to the linear spring and
//    misses the requested e by several per cent for Hertz, so grainlab solves
//    that dimensionless equation (with the no-tension clamp) once per
//    restitution and inverts e(beta) by bisection: restitution_to_beta().
#pragma once

#include <string>

namespace grainlab {

enum class ContactLaw { Hooke, HertzUser, HertzMaterial };

// Parses "hooke", "hertz" (user coefficients) or "hertz-material".
ContactLaw parse_contact_law(const std::string& name);
const char* contact_law_name(ContactLaw law);

// One material. Which fields matter depends on the contact law.
struct Material {
  std::string name = "default";
  double density = 2650;          // kg/m^3
  double friction = 0.5;          // Coulomb mu (inter-grain)
  // Material form (Hertz-material):
  double youngs_modulus = 4e9;    // Pa
  double poisson_ratio = 0.3;
  double restitution = 0.5;       // coefficient of normal restitution, (0, 1]
  // User-coefficient forms (Hooke, Hertz-user):
  double k_n = 1e12;              // Hooke N/m; Hertz N/m^2
  double k_t = 8e11;
  double gamma_n = 40;            // Hooke 1/s; Hertz 1/(m s)
  double gamma_t = 20;
};

// Coefficients of one material pair, mixed once when the model is built.
struct PairCoefficients {
  double k_n = 0, k_t = 0;          // user forms: as in Material; material form: E*, G*
  double gamma_n = 0, gamma_t = 0;  // user forms: as in Material; material form: beta (both)
  double friction = 0;
};

// Mixes two materials for the given law (harmonic E*/G*, the smaller friction
// (the slipperier surface governs: a lubricated wall stays lubricated),
// mean user coefficients, beta from the mean restitution).
PairCoefficients mix(const Material& a, const Material& b, ContactLaw law);

// beta for the Hertz-material damping that gives restitution e exactly
// (see the derivation above). e in (0, 1]; e = 1 gives 0.
double restitution_to_beta(double e);
// The restitution the Hertz-material law gives for damping beta (solves the
// dimensionless impact equation with RK4); inverse of restitution_to_beta.
double hertz_restitution(double beta);

// Throws InputError naming the material and the field if a value is impossible.
void validate(const Material& m, ContactLaw law);

}  // namespace grainlab
