// Materials, and the coefficients of a material pair that a contact law
// mixes from them. Which fields a law reads, and their units, is written in
// the law's own file (dynamics/laws/); the laws are described in
// dynamics/contact_law.h.
#pragma once

#include <string>

namespace grainlab {

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
// The law that mixes them says what each slot holds. T is double, or four
// pairs' values side by side (dynamics/contact_lanes.h).
template <typename T>
struct PairCoefficientsOf {
  T k_n{}, k_t{};          // user forms: as in Material; material form: E*, G*
  T gamma_n{}, gamma_t{};  // user forms: as in Material; material form: beta, beta sqrt(4 G*/E*)
  T friction{};
};
using PairCoefficients = PairCoefficientsOf<double>;

}  // namespace grainlab
