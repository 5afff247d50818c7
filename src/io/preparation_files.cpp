// Index densities and preparation records as JSON (see preparation_files.h).
#include "io/preparation_files.h"

#include "io/json.h"

#include <cmath>

namespace grainlab {

std::string index_cache_key(const DirectShearSpec& spec) {
  const nlohmann::json all = spec_to_json(spec);
  nlohmann::json key;
  key["seed"] = all["seed"];
  key["grains"] = all["grains"];
  key["material"] = all["material"];
  key["normal_stress"] = all["consolidation"]["normal_stress"];
  key["numerics"] = all["numerics"];
  key["numerics"].erase("threads");
  return key.dump();
}

namespace {

nlohmann::json preparations(const std::vector<IndexPreparation>& list) {
  nlohmann::json a = nlohmann::json::array();
  for (const IndexPreparation& p : list)
    a.push_back({{"seed", p.seed}, {"deposition_friction", p.friction}, {"bulk_void_ratio", p.void_ratio},
                 {"whole_box_void_ratio", p.whole_void_ratio}, {"settled", p.settled}, {"steps", p.steps},
                 {"wall_s", p.wall_s}});
  return a;
}

}  // namespace

nlohmann::json to_json(const IndexDensities& d) {
  return {{"e_min", d.e_min},
          {"e_max", d.e_max},
          {"e_min_spread", d.e_min_spread},
          {"e_max_spread", d.e_max_spread},
          {"settled", d.settled()},
          {"grains", d.grains},
          {"box_length_m", d.box_length},
          {"box_height_m", d.box_height},
          {"dense", preparations(d.dense)},
          {"loose", preparations(d.loose)}};
}

nlohmann::json to_json(const std::vector<PreparationTrial>& trials) {
  nlohmann::json a = nlohmann::json::array();
  for (const PreparationTrial& t : trials) {
    nlohmann::json j = {{"deposition_friction", t.friction}, {"void_ratio", t.void_ratio}, {"steps", t.steps},
                        {"wall_s", t.wall_s}};
    if (std::isfinite(t.relative_density)) j["relative_density"] = t.relative_density;
    if (!t.error.empty()) j["error"] = t.error;
    a.push_back(j);
  }
  return a;
}

std::optional<std::pair<double, double>> cached_index_densities(const std::filesystem::path& file,
                                                                const DirectShearSpec& spec) {
  if (!std::filesystem::exists(file)) return std::nullopt;
  const nlohmann::json j = read_json_file(file);
  if (!j.contains("key") || j["key"] != index_cache_key(spec)) return std::nullopt;
  return std::make_pair(j["e_min"].get<double>(), j["e_max"].get<double>());
}

void write_index_densities(const std::filesystem::path& file, const DirectShearSpec& spec, const IndexDensities& d) {
  nlohmann::json j = to_json(d);
  j["key"] = index_cache_key(spec);
  write_json_file(file, j);
}

}  // namespace grainlab
