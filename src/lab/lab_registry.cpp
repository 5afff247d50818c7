// The registry of lab tests: one line per test.
#include "core/error.h"
#include "lab/direct_shear.h"
#include "lab/lab_test.h"
#include "lab/oedometer.h"
#include "lab/triaxial.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace grainlab {

namespace {

using Factory = std::unique_ptr<LabTest> (*)(const DirectShearSpec&);

template <typename Test>
std::unique_ptr<LabTest> make(const DirectShearSpec& spec) {
  return std::make_unique<Test>(spec);
}

struct Entry {
  const char* name;
  Factory factory;
};

constexpr Entry kTests[] = {
    {"direct-shear", &make<DirectShearTest>},
    {"oedometer", &make<OedometerTest>},
    {"triaxial", &make<TriaxialTest>},
};

}  // namespace

std::unique_ptr<LabTest> make_lab_test(const std::string& name, const DirectShearSpec& spec) {
  for (const Entry& e : kTests)
    if (name == e.name) return e.factory(spec);
  input_error("unknown lab test '{}': the registered tests are {}", name, fmt::join(lab_test_names(), ", "));
}

std::vector<std::string> lab_test_names() {
  std::vector<std::string> names;
  for (const Entry& e : kTests) names.emplace_back(e.name);
  return names;
}

}  // namespace grainlab
