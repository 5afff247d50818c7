// The registry of lab tests: each test by name, how to make it, and its own
// config table (lab/spec_keys.h). The built-in tests are one line each in
// lab_registry.cpp; a program may register more before it reads a config
// (register_lab_test), as tests/lab/hold_test.cpp does.
//
// Adding a lab test: its own files only, and one line in lab_registry.cpp.
//   1. lab/<test>.h/.cpp: its settings struct (read with
//      spec.settings<MySpec>()), and a class deriving from PreparedTest
//      (lab/prepared_test.h: the specimen's preparation, lab/preparation.h,
//      the sample observer, the byte helpers) that steps the preparation
//      until prepared(), then loads the specimen its own way, with a static
//      LabTestKeys keys(): its table, its keys (where each lives in its
//      settings), their checks, the key of its final strain.
//   2. lab/lab_registry.cpp: lab_test_entry<MyTest>("my-test").
// The config (parsing, checks, --print-defaults --test my-test, config.toml,
// run.json), the registry's names, checkpoints and io's outputs follow.
#pragma once

#include "lab/lab_test.h"
#include "lab/spec_keys.h"

#include <memory>
#include <string_view>
#include <type_traits>
#include <vector>

namespace grainlab {

using LabTestFactory = std::unique_ptr<LabTest> (*)(const LabSpec&, std::unique_ptr<SpecimenPreparation>);
using PreparationSpecOf = LabSpec (*)(const LabSpec&);

struct LabTestEntry {
  std::string_view name;  // the config's `test` (a literal: it is kept as a view)
  LabTestFactory factory;
  LabTestKeys keys;       // its table; keys.table.test is set to `name`
  // The spec its specimen is prepared with (the closed-box tests close the
  // gap); null: the run's spec as it is.
  PreparationSpecOf preparation_spec = nullptr;
};

// A test that can go on from a preparation of its spec does (make_lab_test).
template <typename Test>
std::unique_ptr<LabTest> make_registered(const LabSpec& spec, std::unique_ptr<SpecimenPreparation> prepared) {
  if constexpr (std::is_constructible_v<Test, const LabSpec&, std::unique_ptr<SpecimenPreparation>>)
    if (prepared) return std::make_unique<Test>(spec, std::move(prepared));
  return std::make_unique<Test>(spec);
}

// The entry of test class Test (with its static keys(), and its static
// preparation_spec(spec) if it prepares in another box) under `name`.
template <typename Test>
LabTestEntry lab_test_entry(std::string_view name) {
  PreparationSpecOf preparation = nullptr;
  if constexpr (requires(const LabSpec& s) { Test::preparation_spec(s); }) preparation = &Test::preparation_spec;
  return {name, &make_registered<Test>, Test::keys(), preparation};
}

// The spec test `name` prepares its specimen with (InputError for an
// unknown test): what the preparation search's trials use, so that the
// trial that lands on the target is the test's own specimen.
LabSpec lab_preparation_spec(const std::string& name, const LabSpec& spec);

// Adds a test (InputError if its name or table is taken).
void register_lab_test(LabTestEntry entry);
// The registered tests, in registration order (the built-in ones first).
const std::vector<LabTestEntry>& lab_test_entries();

}  // namespace grainlab
