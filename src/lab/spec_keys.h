// What a config key is: its table, name, unit/meaning and where its value
// lives in a LabSpec; and a lab test's own table of keys (its settings),
// which the test registers with itself (lab/lab_registry.h). io's config
// (io/config.cpp, io/spec_fields.h) walks the shared keys and every
// registered test's, so a test adds its keys in its own files.
#pragma once

#include "dynamics/contact_law.h"
#include "dynamics/law_parameters.h"

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace grainlab {

struct LabSpec;

// A typed pointer to one field of a LabSpec.
using SpecFieldRef = std::variant<double*, int*, std::string*, std::uint64_t*, ContactLaw*, std::vector<double>*>;

// One config key.
struct SpecField {
  std::string_view table;               // "" for a top-level key
  std::string_view key;                 // the struct field name
  std::string doc;                      // unit and meaning (one line)
  std::function<SpecFieldRef(LabSpec&)> ref;  // where the value lives
  const LawParameter* parameter = nullptr;     // a contact law's parameter (dynamics/law_parameters.h), or null

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

// A check of one value: when `ok` is false, the config refuses `key` (its
// value, where the file sets it, and `rule`: what it must be).
using SpecNeed = std::function<void(bool ok, std::string_view key, SpecFieldRef value, std::string_view rule)>;

// A lab test's own table: its keys (into its settings struct, held by
// LabSpec::settings), their checks, and which of its keys ends the loading
// in strain (output.strain_interval may not exceed it; "" = none).
struct LabTestKeys {
  SpecTable table;
  std::vector<SpecField> fields;
  void (*validate)(LabSpec& spec, const SpecNeed& need) = nullptr;
  std::string_view final_strain_key = "";
};

}  // namespace grainlab
