// Before `grainlab run` steps: the grains' own index void ratios (from the
// config, from the run folder's index_densities.json when its inputs match,
// or measured), and the deposition friction (from the config, or chosen by
// the preparation search, whose matching trial becomes the run's specimen).
// Each preparation, index or trial, is kept in the run folder while it runs
// (io/kept_preparations.h), so that a stopped or killed run goes on from
// there. Written to output.folder/preparation.json; --resume reads it back. With
// specimen.from (another run's prepared specimen) nothing is prepared: the
// record is that run's preparation.json plus "specimen_from", and the caller
// loads the specimen into the test.
#pragma once

#include "io/checkpoint.h"
#include "lab/lab_test.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>

namespace grainlab::apps {

struct PreparedRun {
  std::unique_ptr<LabTest> test;  // ready to run (compacted already when the search chose the friction)
  nlohmann::json record;          // what preparation.json holds (run.json "specimen_preparation")
  std::optional<Checkpoint> specimen;  // specimen.from's state and protocol, to load into the test
};

// Resolves spec as above and builds the test. On resume only reads
// preparation.json. When `stop` returns true while the index densities are
// measured or the deposition friction searched, the preparation in progress
// is kept and Stopped (core/error.h) thrown.
PreparedRun prepare_run(const LabSpec& spec, const std::filesystem::path& out, bool resume,
                        const std::function<bool()>& stop = {});

}  // namespace grainlab::apps
