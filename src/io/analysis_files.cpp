// The files of analysis/ (contents in analysis_files.h).
#include "io/analysis_files.h"

#include "analysis/fabric.h"
#include "analysis/kanatani.h"
#include "core/error.h"
#include "io/atomic_file.h"
#include "io/json.h"
#include "io/shear_analysis.h"
#include "io/table.h"

#include <fmt/format.h>

#include <system_error>

namespace grainlab {

namespace {

nlohmann::json matrix_json(const Mat3& m) {
  nlohmann::json j = nlohmann::json::array();
  for (int i = 0; i < 3; ++i) j.push_back({m(i, 0), m(i, 1), m(i, 2)});
  return j;
}

nlohmann::json tensor4_json(const analysis::Tensor4& t) {  // nested [i][j][k][l]
  nlohmann::json out = nlohmann::json::array();
  for (int i = 0; i < 3; ++i) {
    nlohmann::json ti = nlohmann::json::array();
    for (int j = 0; j < 3; ++j) {
      nlohmann::json tij = nlohmann::json::array();
      for (int k = 0; k < 3; ++k) tij.push_back({t(i, j, k, 0), t(i, j, k, 1), t(i, j, k, 2)});
      ti.push_back(std::move(tij));
    }
    out.push_back(std::move(ti));
  }
  return out;
}

std::string profile_csv(const analysis::DisplacementProfile& p) {
  Table t;
  t.columns = {"z_m", "displacement_x_m", "count"};
  for (std::size_t k = 0; k < p.z.size(); ++k) t.add_row({p.z[k], p.u[k], static_cast<double>(p.count[k])});
  return t.to_csv();
}

nlohmann::json band_json(const BandAnalysis& b) {
  const auto or_null = [&](double v) { return b.band.found ? nlohmann::json(v) : nlohmann::json(nullptr); };
  nlohmann::json j;
  j["found"] = b.band.found;
  j["low_m"] = or_null(b.band.z_low);
  j["high_m"] = or_null(b.band.z_high);
  j["mid_m"] = or_null(b.band.z_mid);
  j["u_bottom_m"] = or_null(b.band.u_bottom);
  j["u_top_m"] = or_null(b.band.u_top);
  j["grains_in_band"] = analysis::mask_count(b.mask);
  j["layers"] = b.profile_spec.layers;
  j["layer_thickness_m"] = (b.profile.z_max - b.profile.z_min) / b.profile_spec.layers;
  j["method"] = fmt::format(
      "horizontal displacement since the start of shear, binned by reference height into {} layers of "
      "about one mean grain diameter from the floor (z = 0) to the cap; band where the displacement "
      "normalised between its plateaus (medians of the lowest and highest fifth of the layers) runs from "
      "0.1 to 0.9 around its middle (analysis/shear_band.h); no band unless the plateaus differ by at least "
      "10 % of the box displacement ({:.3g} m)",
      b.profile_spec.layers, b.min_jump);
  return j;
}

std::string force_chains_csv(const State& s) {
  Table t;
  t.columns = {"x1_m", "y1_m", "z1_m", "x2_m", "y2_m", "z2_m", "force_N", "tangential_force_N"};
  for (const Contact& pc : s.contacts) {
    if (!in_contact(pc)) continue;
    const Vec3& a = s.bodies[pc.a].x;
    const Vec3& b = s.bodies[pc.b].x;
    const Vec3 n = pc.geo.normal.normalized();
    const double tangential = (pc.force - pc.force.dot(n) * n).norm();
    t.add_row({a.x(), a.y(), a.z(), b.x(), b.y(), b.z(), pc.normal_force, tangential});
  }
  return t.to_csv();
}

}  // namespace

nlohmann::json fabric_entry(const State& state, const analysis::GrainMask* mask, std::size_t max_normals) {
  const std::vector<Vec3> normals = analysis::contact_normals(state, mask);
  nlohmann::json j;
  j["contacts"] = normals.size();
  if (normals.empty()) {
    j["note"] = "no grain-grain contacts in this set";
    return j;
  }
  const analysis::FabricTensors f = analysis::fabric_tensors(normals);
  const analysis::KanataniDensity k = analysis::kanatani_density(f);
  const analysis::Principal p = analysis::principal(f.phi);
  j["phi"] = matrix_json(f.phi);
  j["D2"] = matrix_json(k.D2);
  j["D4"] = tensor4_json(k.D4);
  j["principal_values"] = {p.values[0], p.values[1], p.values[2]};
  j["principal_directions"] = matrix_json(p.directions);
  j["psi"] = analysis::octahedral_fabric_factor(p.values);
  const std::size_t n = normals.size(), m = std::min(n, std::max<std::size_t>(1, max_normals));
  nlohmann::json list = nlohmann::json::array();
  for (std::size_t i = 0; i < m; ++i) {
    const Vec3 v = normals[i * n / m].normalized();  // i n / m: evenly spread over the list
    list.push_back({v.x(), v.y(), v.z()});
  }
  j["normals"] = std::move(list);
  j["normals_subsampled"] = m < n;
  j["normals_total"] = n;
  j["normals_written"] = m;
  return j;
}

void write_analysis_files(const LabTest& test, const std::filesystem::path& folder) {
  const std::filesystem::path dir = folder / "analysis";
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw RunError(fmt::format("cannot create '{}': {}", dir.string(), ec.message()));
  const State& now = test.world().state;
  const State ref = shear_reference_state(test);
  if (ref.bodies.size() != now.bodies.size())
    throw RunError("write_analysis_files: the test has not reached shear (no reference state)");
  const BandAnalysis b = analyse_band(test, ref);
  write_file_atomically(dir / "profile.csv", profile_csv(b.profile));
  write_json_file(dir / "band.json", band_json(b));
  nlohmann::json fabric;
  fabric["all"] = fabric_entry(now, nullptr);
  if (b.band.found && analysis::mask_count(b.mask) > 0) {
    fabric["band"] = fabric_entry(now, &b.mask);
  } else {
    fabric["band"] = {{"contacts", 0}, {"note", "no shear band found"}};
  }
  fabric["band"]["low_m"] = b.band.found ? nlohmann::json(b.band.z_low) : nlohmann::json(nullptr);
  fabric["band"]["high_m"] = b.band.found ? nlohmann::json(b.band.z_high) : nlohmann::json(nullptr);
  fabric["note"] = "unit normals of grain-grain contacts (sign-free); band: the contacts of the grains whose "
                   "reference centre is in the band, each once per such grain (as CN_S counts them)";
  write_json_file(dir / "fabric.json", fabric);
  write_file_atomically(dir / "force_chains.csv", force_chains_csv(now));
}

}  // namespace grainlab
