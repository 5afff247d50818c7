// JSON helpers for run.json (nlohmann::json): the run's inputs as a nested
// object with the same keys as the TOML config, and an atomic writer.
#pragma once

#include "lab/lab_spec.h"

#include <nlohmann/json.hpp>

#include <filesystem>

namespace grainlab {

// The spec as {"seed": ..., "grains": {...}, "material": {...}, ...}, keys as in the config file.
nlohmann::json spec_to_json(const LabSpec& spec);

// Writes j (pretty-printed, 2-space indent, trailing newline) to path atomically (RunError on failure).
void write_json_file(const std::filesystem::path& path, const nlohmann::json& j);

// Reads a JSON file; InputError naming the file (and the byte offset of a syntax error) on failure.
nlohmann::json read_json_file(const std::filesystem::path& path);

}  // namespace grainlab
