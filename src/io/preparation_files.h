// The run folder's record of how the specimen was prepared:
// index_densities.json (the grains' own e_min/e_max, with every preparation
// and the key of the inputs they depend on, reused by later runs with the
// same key) and preparation.json (the own indices and deposition friction
// the run used, and the search's trials; --resume rebuilds the run from it).
#pragma once

#include "lab/index_densities.h"
#include "lab/preparation_search.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <optional>

namespace grainlab {

// The inputs the own indices depend on (grains, material, consolidation
// stress, numerics but the thread count and the loading speed, seed) as one
// JSON string.
std::string index_cache_key(const LabSpec& spec);

nlohmann::json to_json(const IndexDensities& d);
nlohmann::json to_json(const std::vector<PreparationTrial>& trials);

// e_min, e_max from a finished index_densities.json whose key matches
// spec's; nullopt otherwise.
std::optional<std::pair<double, double>> cached_index_densities(const std::filesystem::path& file,
                                                                const LabSpec& spec);

// The preparations of an unfinished index_densities.json whose key matches
// spec's (to pass to measure_index_densities as `done`); empty lists
// otherwise.
IndexDensities unfinished_index_densities(const std::filesystem::path& file, const LabSpec& spec);

// Writes index_densities.json (with the key). finished = false writes the
// preparations made so far, marked "finished": false and without e_min and
// e_max, which cached_index_densities does not take.
void write_index_densities(const std::filesystem::path& file, const LabSpec& spec, const IndexDensities& d,
                           bool finished = true);

}  // namespace grainlab
