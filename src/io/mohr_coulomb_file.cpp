// mohr_coulomb.json of a triaxial comparison (definitions in mohr_coulomb_file.h).
#include "io/mohr_coulomb_file.h"

#include "analysis/mohr_coulomb.h"
#include "core/error.h"
#include "io/json.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

namespace grainlab {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// j[k0][k1]... as a finite number, or nullopt.
std::optional<double> number(const json& j, std::initializer_list<const char*> keys) {
  const json* at = &j;
  for (const char* k : keys) {
    if (!at->is_object() || !at->contains(k)) return std::nullopt;
    at = &(*at)[k];
  }
  if (!at->is_number() || !std::isfinite(at->get<double>())) return std::nullopt;
  return at->get<double>();
}

json or_null(std::optional<double> v) { return v ? json(*v) : json(nullptr); }

struct Run {
  fs::path folder;
  json info;
  std::optional<double> sigma3;
};

struct Envelope {
  const char* name;   // key in the file
  const char* ratio;  // triaxial.<ratio>: eta
  const char* angle;  // triaxial.<angle>: the run's own phi'
};
constexpr Envelope kEnvelopes[] = {{"peak", "peak_stress_ratio", "peak_friction_angle_deg"},
                                   {"critical_state", "critical_stress_ratio", "critical_friction_angle_deg"}};

// The run's state at an envelope (the file's run entry), or null without its stresses.
json state(const Run& r, const Envelope& env) {
  const std::optional<double> eta = number(r.info, {"triaxial", env.ratio});
  if (!r.sigma3 || !eta) return nullptr;
  double s1 = 0;
  try {
    s1 = analysis::triaxial_sigma1(*r.sigma3, *eta);
  } catch (const InputError&) {
    return nullptr;
  }
  const analysis::MohrCircle c = analysis::mohr_circle(s1, *r.sigma3);
  return {{"stress_ratio", *eta}, {"sigma1_Pa", s1}, {"sigma3_Pa", *r.sigma3}, {"s_Pa", c.s}, {"t_Pa", c.t},
          {"friction_angle_deg", or_null(number(r.info, {"triaxial", env.angle}))}};
}

json fit(const std::vector<analysis::MohrCircle>& circles) {
  try {
    const analysis::MohrCoulombFit f = analysis::fit_mohr_coulomb(circles);
    return {{"phi_deg", f.phi_deg}, {"c_Pa", f.c},           {"a_Pa", f.a},
            {"sin_phi", f.sin_phi}, {"r_squared", f.r_squared}, {"rms_residual_Pa", f.rms_residual},
            {"runs", f.circles}};
  } catch (const InputError& e) {
    return {{"phi_deg", nullptr}, {"c_Pa", nullptr}, {"refused", e.what()}};
  }
}

}  // namespace

bool is_triaxial_comparison(const std::vector<fs::path>& runs) {
  if (runs.size() < 2) return false;
  for (const fs::path& r : runs) {
    try {
      const json j = read_json_file(r / "run.json");
      if (!j.is_object() || !j.contains("config") || j["config"].value("test", "") != "triaxial") return false;
    } catch (const InputError&) {
      return false;
    }
  }
  return true;
}

void write_mohr_coulomb_file(const std::vector<fs::path>& folders, const fs::path& out_dir) {
  std::vector<Run> runs;
  for (const fs::path& f : folders) {
    Run r{fs::canonical(f), read_json_file(f / "run.json"), std::nullopt};
    r.sigma3 = number(r.info, {"config", "consolidation", "normal_stress"});
    runs.push_back(std::move(r));
  }
  std::stable_sort(runs.begin(), runs.end(), [](const Run& a, const Run& b) {
    return std::make_pair(!a.sigma3, a.sigma3.value_or(0)) < std::make_pair(!b.sigma3, b.sigma3.value_or(0));
  });
  json doc = {
      {"what", "Mohr-Coulomb envelopes tau = c' + sigma' tan(phi') fitted over drained triaxial runs: least "
               "squares of t = (sigma_1 - sigma_3)/2 on s' = (sigma_1 + sigma_3)/2, t = a + s' sin(phi'), "
               "c' = a / cos(phi')"},
      {"source", "run.json: config.consolidation.normal_stress as sigma_3; triaxial.peak_stress_ratio and "
                 "critical_stress_ratio as eta, sigma_1 = sigma_3 (3 + 2 eta) / (3 - eta)"}};
  json entries = json::array();
  for (const Run& r : runs)
    entries.push_back({{"name", r.folder.filename().string()}, {"folder", r.folder.string()},
                       {"sigma3_Pa", or_null(r.sigma3)}});
  for (const Envelope& env : kEnvelopes) {
    std::vector<analysis::MohrCircle> circles;
    for (std::size_t k = 0; k < runs.size(); ++k) {
      const json s = state(runs[k], env);
      if (!s.is_null()) circles.push_back({s["s_Pa"].get<double>(), s["t_Pa"].get<double>()});
      entries[k][env.name] = s;
    }
    doc[env.name] = fit(circles);
  }
  doc["runs"] = std::move(entries);
  fs::create_directories(out_dir);
  write_json_file(out_dir / "mohr_coulomb.json", doc);
}

}  // namespace grainlab
