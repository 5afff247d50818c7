// The one list of config keys: table, key, unit/meaning, and where the value
// lives in a DirectShearSpec. Parsing, validation, the default config,
// to_toml and the JSON summary all walk this list, so a key is added once.
// The contact laws' parameters are in it as flat [material] keys, taken from
// the registered laws' parameter lists (dynamics/law_parameters.h).
#pragma once

#include "lab/direct_shear_spec.h"

#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace grainlab {

// A typed pointer to one field of a DirectShearSpec.
using SpecFieldRef = std::variant<double*, int*, std::string*, std::uint64_t*, ContactLaw*, std::vector<double>*>;

// One config key.
struct SpecField {
  std::string_view table;               // "" for a top-level key
  std::string_view key;                 // the struct field name
  std::string_view doc;                 // unit and meaning (one line)
  std::function<SpecFieldRef(DirectShearSpec&)> ref;  // where the value lives
  const LawParameter* parameter = nullptr;  // a contact law's parameter (dynamics/law_parameters.h), or null

  // "table.key" (or "key" at top level), as used in messages.
  std::string dotted() const {
    return table.empty() ? std::string(key) : std::string(table) + "." + std::string(key);
  }
};

// One config table with its meaning.
struct SpecTable {
  std::string_view name;
  std::string_view doc;
  std::string_view test = "";  // the one lab test that reads it ("" = every test)
};

// All keys, in file order (top-level keys first, then table by table).
std::span<const SpecField> spec_fields();
// All tables, in file order.
std::span<const SpecTable> spec_tables();

}  // namespace grainlab
