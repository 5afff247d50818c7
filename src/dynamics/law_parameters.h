// A contact law's own parameters: what a law declares about each value it
// reads from a Material (config key, unit, meaning, valid range, default),
// so that validation, the config file ([material.<law>] tables and the flat
// [material] keys) and its documentation come from the law alone.
//
// A parameter's value lives in a Material field (the built-in laws') or,
// for any other law, in Material::more under its key. Two laws that declare
// the same key share one value (hooke's and hertz's k_n, as the flat key
// k_n always did).
#pragma once

#include "dynamics/material.h"

#include <cmath>

namespace grainlab {

struct LawParameter {
  const char* key;          // config key, e.g. "youngs_modulus"
  const char* unit;         // SI unit, "" for a pure number
  const char* meaning;      // one line
  const char* rule;         // the valid range, for messages, e.g. "> 0"
  bool (*ok)(double);       // the check of `rule` (finiteness is checked for every parameter)
  double fallback = 0;      // default, where the value lives in Material::more
  double Material::*field = nullptr;  // the Material field holding it; nullptr: Material::more

  // True if v is finite and within the rule.
  bool accepts(double v) const { return std::isfinite(v) && ok(v); }
};

// The value of parameter p in material m.
inline double parameter_value(const Material& m, const LawParameter& p) {
  if (p.field) return m.*p.field;
  const double* v = m.more.find(p.key);
  return v ? *v : p.fallback;
}
inline double& parameter_value(Material& m, const LawParameter& p) {
  return p.field ? m.*p.field : m.more.at(p.key, p.fallback);
}

// The usual rules' checks.
namespace law_rule {
inline constexpr bool positive(double v) { return v > 0; }
inline constexpr bool non_negative(double v) { return v >= 0; }
}  // namespace law_rule

}  // namespace grainlab
