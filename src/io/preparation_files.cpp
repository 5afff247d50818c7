// Index densities and preparation records as JSON (see preparation_files.h).
#include "io/preparation_files.h"

#include "io/json.h"

#include <cmath>

namespace grainlab {

std::string index_cache_key(const LabSpec& spec) {
  const nlohmann::json all = spec_to_json(spec);
  nlohmann::json key;
  key["seed"] = all["seed"];
  key["grains"] = all["grains"];
  key["material"] = all["material"];
  key["normal_stress"] = all["consolidation"]["normal_stress"];
  key["numerics"] = all["numerics"];
  key["numerics"].erase("threads");
  // The loading speed (shear, axial, oedometer stages) is set after the
  // specimen is prepared: any value keys as the default, so the key of a
  // default-speed spec is the one it always was (index_densities.json files,
  // the embedded default's indices).
  key["numerics"]["inertial_number"] = spec_to_json(LabSpec{})["numerics"]["inertial_number"];
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

std::vector<IndexPreparation> preparations_from_json(const nlohmann::json& a) {
  std::vector<IndexPreparation> list;
  for (const nlohmann::json& j : a) {
    IndexPreparation p;
    p.seed = j.at("seed").get<std::uint64_t>();
    p.friction = j.at("deposition_friction").get<double>();
    p.void_ratio = j.at("bulk_void_ratio").get<double>();
    p.whole_void_ratio = j.at("whole_box_void_ratio").get<double>();
    p.settled = j.at("settled").get<bool>();
    p.steps = j.at("steps").get<std::int64_t>();
    p.wall_s = j.at("wall_s").get<double>();
    list.push_back(p);
  }
  return list;
}

// The file's JSON when its key matches spec's and it is finished (or not); null otherwise.
nlohmann::json matching_index_file(const std::filesystem::path& file, const LabSpec& spec, bool finished) {
  if (!std::filesystem::exists(file)) return nullptr;
  nlohmann::json j = read_json_file(file);
  if (!j.contains("key") || j["key"] != index_cache_key(spec)) return nullptr;
  if (j.value("finished", true) != finished) return nullptr;
  return j;
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
                                                                const LabSpec& spec) {
  const nlohmann::json j = matching_index_file(file, spec, true);
  if (j.is_null()) return std::nullopt;
  return std::make_pair(j["e_min"].get<double>(), j["e_max"].get<double>());
}

IndexDensities unfinished_index_densities(const std::filesystem::path& file, const LabSpec& spec) {
  IndexDensities d;
  const nlohmann::json j = matching_index_file(file, spec, false);
  if (j.is_null()) return d;
  d.dense = preparations_from_json(j.at("dense"));
  d.loose = preparations_from_json(j.at("loose"));
  return d;
}

void write_index_densities(const std::filesystem::path& file, const LabSpec& spec, const IndexDensities& d,
                           bool finished) {
  nlohmann::json j = to_json(d);
  if (!finished) {
    for (const char* mean : {"e_min", "e_max", "e_min_spread", "e_max_spread", "settled", "grains"}) j.erase(mean);
    j["finished"] = false;
  }
  j["key"] = index_cache_key(spec);
  write_json_file(file, j);
}

}  // namespace grainlab
