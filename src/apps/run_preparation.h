// Before `grainlab run` steps: the grains' own index void ratios (from the
// config, from the run folder's index_densities.json when its inputs match,
// or measured), and the deposition friction (from the config, or chosen by
// the preparation search, whose matching trial becomes the run's specimen).
// Written to output.folder/preparation.json; --resume reads it back.
#pragma once

#include "lab/lab_test.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <memory>

namespace grainlab::apps {

struct PreparedRun {
  std::unique_ptr<LabTest> test;  // ready to run (compacted already when the search chose the friction)
  nlohmann::json record;          // what preparation.json holds (run.json "specimen_preparation")
};

// Resolves spec as above and builds the test. On resume only reads preparation.json.
PreparedRun prepare_run(const DirectShearSpec& spec, const std::filesystem::path& out, bool resume);

}  // namespace grainlab::apps
