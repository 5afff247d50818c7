// The one list of config keys: table, key, unit/meaning, and where the value
// lives in a LabSpec (lab/spec_keys.h). Parsing, validation, the default
// config, to_toml and the JSON summary all walk this list, so a key is added
// once: the shared keys in io/config.cpp, each lab test's own in its own
// files, registered with the test (lab/lab_registry.h).
#pragma once

#include "lab/lab_spec.h"
#include "lab/spec_keys.h"

#include <vector>

namespace grainlab {

// All keys, in file order (top-level keys first, then table by table; the
// registered tests' tables after [consolidation], in registration order).
const std::vector<SpecField>& spec_fields();
// All tables, in file order.
const std::vector<SpecTable>& spec_tables();

}  // namespace grainlab
