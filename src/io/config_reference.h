// The configuration reference (docs/config.md), generated from the commented
// default configs that `grainlab run --print-defaults --test T` writes for
// every registered lab test: each table with its meaning and the tests that
// read it, each key with its default, unit and meaning. Built from the same
// key list the parser walks, so the page cannot drift from the code
// (tests/io/config_reference_test.cpp compares the two).
#pragma once

#include <string>

namespace grainlab {

// docs/config.md's full text (Markdown).
std::string config_reference_markdown();

}  // namespace grainlab
