// What a contact law is, and the one routine that applies any law.
//
// Symbols (paper section 2.2, DESIGN.md "Contact physics"): overlap delta (m),
// unit normal n from body a to body b, effective mass m* = m_a m_b/(m_a+m_b),
// effective radius R* = R_a R_b/(R_a+R_b), normal relative velocity
// v_n = (v_b - v_a).n (negative while approaching), tangential part v_t.
//
// Every law is reduced, at the current overlap, to four coefficients
//     f_n = K_n delta - C_n v_n          (clamped at 0: no tension)
//     f_t = -K_t xi   - C_t v_t          (capped by Coulomb, mu f_n)
// where xi is the tangential spring (m). A law lives in one file under
// dynamics/laws/ (its derivation at the top) as a struct of static functions:
//     name, description             config name; one line for messages
//     parameters                    its own parameters (dynamics/law_parameters.h): key, unit,
//                                   meaning, valid range; validation and the config read them
//     pair_slots                    how many of PairCoefficients::c its mix fills
//     mix(Material, Material)       PairCoefficients::c of a material pair (mix() below adds friction)
//     at(pair, delta, R*, m*)       K_n, C_n, K_t, C_t at this overlap (inline: the hot path;
//                                   a template over the number type, root() for square roots,
//                                   so that four contacts go at once: contact_lanes.h)
//     stiffness(LawCoefficients)    d f_n / d delta of the elastic force, from at()'s coefficients
//     tangent_stiffness(f_n, delta) the same, from a contact's elastic force and overlap
//     elastic_energy(f_n, delta)    integral of the elastic f_n from 0 to delta
// and is registered by one line in dynamics/laws/registry.h. A ContactLaw is a
// handle to a registered law; the force loop is instantiated once per law
// (World::forces_with<Law>), so no call per contact goes through a pointer.
#pragma once

#include "core/types.h"
#include "dynamics/law_parameters.h"
#include "dynamics/material.h"

#include <cmath>
#include <cstdint>
#include <span>
#include <string>

namespace grainlab {

// A law's coefficients at the current overlap (T: double, or four contacts'
// side by side, dynamics/contact_lanes.h).
template <typename T>
struct LawCoefficientsOf {
  T k_n, c_n, k_t, c_t;
};
using LawCoefficients = LawCoefficientsOf<double>;

// The square root of a double; the laws call root() so that their at() is
// written once for one contact and for four (contact_lanes.h overloads it).
inline double root(double x) { return std::sqrt(x); }

// What the engine and the lab may ask of a registered law (the law's static
// functions, behind pointers; none of them is called per contact per step).
struct ContactLawEntry {
  const char* name;         // config name, e.g. "hertz-material"
  const char* description;  // one line, for messages
  std::span<const LawParameter> parameters;
  int pair_slots;           // slots of PairCoefficients::c that mix fills
  PairCoefficients (*mix)(const Material& a, const Material& b);
  LawCoefficients (*at)(const PairCoefficients& p, double delta, double r_eff, double m_eff);
  double (*stiffness)(const LawCoefficients& k);
  double (*tangent_stiffness)(double f_n, double delta);
  double (*elastic_energy)(double f_n, double delta);
};

// A handle to a registered contact law: cheap to copy, compares by identity.
// Default-constructed, it is the registry's default law.
class ContactLaw {
 public:
  ContactLaw();
  // The registered law at position `index` of the registry.
  static ContactLaw at_index(std::size_t index);
  // Position in the registry (selects the force kernel).
  std::size_t index() const { return index_; }
  // The law's functions.
  const ContactLawEntry& operator*() const;
  const ContactLawEntry* operator->() const { return &**this; }
  friend bool operator==(ContactLaw, ContactLaw) = default;

 private:
  std::uint8_t index_;
};

// The law registered under `name` ("hooke", "hertz", "hertz-material", ...);
// InputError listing the registered names otherwise.
ContactLaw parse_contact_law(const std::string& name);
// The config name of a law.
const char* contact_law_name(ContactLaw law);
// Every registered name, quoted and comma-separated (for messages).
std::string contact_law_names();
// Every registered law's entry, in registry order.
std::span<const ContactLawEntry> contact_laws();
// "name" (description: key (unit), ...), for messages and documentation.
std::string contact_law_summary(const ContactLawEntry& law);

// Mixes two materials for the law: the smaller friction (the slipperier
// surface governs: a lubricated wall stays lubricated) and the law's own rule.
PairCoefficients mix(const Material& a, const Material& b, ContactLaw law);
// Throws InputError naming the material and the field if a value is impossible
// (density and friction for every law, then the law's own parameters, by
// their rules).
void validate(const Material& m, ContactLaw law);
// "rule (unit)": how a parameter's valid range reads in messages.
std::string parameter_rule(const LawParameter& p);

// Damping torque on b of an extended patch (a face lying on a wall).
// The normal damping -C_n v_n acts on every point of the patch; with v_n
// varying as (w x s).n over patch offsets s, the part beyond the force at the
// centroid is a torque -C_n D w with D = sum_i w_i (s_i x n)(s_i x n)^T, which
// for an isotropic patch of spread s2 = sum_i w_i |s_i|^2 is (s2/2)(I - n n^T).
// Without it a single contact point leaves the rocking of a flat face undamped.
inline Vec3 patch_damping_torque(double c_n, double spread, const Vec3& normal, const Vec3& w_rel) {
  return -c_n * 0.5 * spread * (w_rel - w_rel.dot(normal) * normal);
}

}  // namespace grainlab
