// The registry of lab tests: one line per built-in test (lab_registry.h).
#include "lab/lab_registry.h"

#include "core/error.h"
#include "lab/direct_shear.h"
#include "lab/oedometer.h"
#include "lab/preparation.h"
#include "lab/triaxial.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace grainlab {

namespace {

std::vector<LabTestEntry>& entries() {
  static std::vector<LabTestEntry> tests = [] {
    std::vector<LabTestEntry> builtin = {
        lab_test_entry<DirectShearTest>("direct-shear"),
        lab_test_entry<OedometerTest>("oedometer"),
        lab_test_entry<TriaxialTest>("triaxial"),
    };
    for (LabTestEntry& e : builtin) e.keys.table.test = e.name;
    return builtin;
  }();
  return tests;
}

[[noreturn]] void unknown_test(const std::string& name) {
  input_error("unknown lab test '{}': the registered tests are {}", name, fmt::join(lab_test_names(), ", "));
}

}  // namespace

void register_lab_test(LabTestEntry entry) {
  for (const LabTestEntry& e : entries())
    if (e.name == entry.name || e.keys.table.name == entry.keys.table.name)
      input_error("lab test '{}' (table [{}]) is registered already", entry.name, entry.keys.table.name);
  entry.keys.table.test = entry.name;
  entries().push_back(std::move(entry));
}

const std::vector<LabTestEntry>& lab_test_entries() { return entries(); }

std::unique_ptr<LabTest> make_lab_test(const std::string& name, const LabSpec& spec,
                                       std::unique_ptr<SpecimenPreparation> prepared) {
  for (const LabTestEntry& e : entries())
    if (name == e.name) return e.factory(spec, std::move(prepared));
  unknown_test(name);
}

LabSpec lab_preparation_spec(const std::string& name, const LabSpec& spec) {
  for (const LabTestEntry& e : entries())
    if (name == e.name) return e.preparation_spec ? e.preparation_spec(spec) : spec;
  unknown_test(name);
}

std::unique_ptr<LabTest> make_lab_test(const std::string& name, const LabSpec& spec) {
  return make_lab_test(name, spec, nullptr);
}

std::vector<std::string> lab_test_names() {
  std::vector<std::string> names;
  for (const LabTestEntry& e : entries()) names.emplace_back(e.name);
  return names;
}

}  // namespace grainlab
