// Materials, and the coefficients of a material pair that a contact law
// mixes from them. A law declares its own parameters (their config keys,
// units, defaults and valid ranges: dynamics/law_parameters.h, listed in the
// law's file under dynamics/laws/); a Material holds their values.
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace grainlab {

// Values of the law parameters that have no field of their own in Material,
// by config key (a law's parameter list says where each value lives).
struct LawValues {
  std::vector<std::pair<std::string, double>> values;

  // The value under `key`, or nullptr.
  const double* find(std::string_view key) const {
    for (const auto& [k, v] : values)
      if (k == key) return &v;
    return nullptr;
  }
  // The value under `key`, added with `fallback` if absent.
  double& at(std::string_view key, double fallback) {
    for (auto& [k, v] : values)
      if (k == key) return v;
    return values.emplace_back(std::string(key), fallback).second;
  }
};

// One material: the law-independent values and the values of the laws'
// parameters. The built-in laws' parameters are fields (the lab's presets and
// the tests set them by name); any other law's live in `more`.
struct Material {
  std::string name = "default";
  double density = 2650;          // kg/m^3
  double friction = 0.5;          // Coulomb mu (inter-grain)
  // Parameters of hertz-material (dynamics/laws/hertz_material.h):
  double youngs_modulus = 4e9;    // Pa
  double poisson_ratio = 0.3;
  double restitution = 0.5;       // coefficient of normal restitution, (0, 1]
  // Parameters of hooke and hertz (dynamics/laws/user_coefficients.h):
  double k_n = 1e12;              // Hooke N/m; Hertz N/m^2
  double k_t = 8e11;
  double gamma_n = 40;            // Hooke 1/s; Hertz 1/(m s)
  double gamma_t = 20;
  // Parameters of other laws, by key.
  LawValues more;
};

// How many mixed coefficients a pair can hold (a law uses the first
// Law::pair_slots of them).
inline constexpr int kPairSlots = 4;

// Coefficients of one material pair, mixed once when the model is built.
// The law that mixes them says what each slot of `c` holds. T is double, or
// four pairs' values side by side (dynamics/contact_lanes.h).
template <typename T>
struct PairCoefficientsOf {
  std::array<T, kPairSlots> c{};  // the law's mixed coefficients
  T friction{};
};
using PairCoefficients = PairCoefficientsOf<double>;

}  // namespace grainlab
