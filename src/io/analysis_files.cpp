// The files of analysis/ (contents in analysis_files.h).
#include "io/analysis_files.h"

#include "analysis/dilation.h"
#include "analysis/force_chains.h"
#include "core/error.h"
#include "core/atomic_file.h"
#include "io/json.h"
#include "io/run_summary.h"
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

// A row-major rows x (values / rows) grid as nested arrays.
nlohmann::json grid_json(const std::vector<double>& values, std::size_t rows) {
  nlohmann::json out = nlohmann::json::array();
  const std::size_t cols = rows ? values.size() / rows : 0;
  for (std::size_t r = 0; r < rows; ++r)
    out.push_back(std::vector<double>(values.begin() + r * cols, values.begin() + (r + 1) * cols));
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

std::string force_chains_csv(const std::vector<analysis::ForceSegment>& segments) {
  Table t;
  t.columns = {"x1_m", "y1_m", "z1_m", "x2_m", "y2_m", "z2_m", "force_N", "tangential_force_N", "strong"};
  for (const analysis::ForceSegment& s : segments)
    t.add_row({s.a.x(), s.a.y(), s.a.z(), s.b.x(), s.b.y(), s.b.z(), s.normal_force, s.tangential_force,
               s.strong ? 1.0 : 0.0});
  return t.to_csv();
}

std::string derived_csv(const LabTest& test) {
  const std::vector<double> strain = series_column(test, "shear_strain");
  const std::vector<double> psi = analysis::dilation_angle_series(series_column(test, "horizontal_displacement_m"),
                                                                  series_column(test, "vertical_displacement_m"));
  Table t;
  t.columns = {"shear_strain", "dilation_angle_deg"};
  for (std::size_t k = 0; k < strain.size() && k < psi.size(); ++k) t.add_row({strain[k], psi[k]});
  return t.to_csv();
}

}  // namespace

nlohmann::json fabric_json(const analysis::FabricResult& f, std::size_t max_normals) {
  nlohmann::json j;
  j["contacts"] = f.contacts;
  if (f.contacts == 0) {
    j["note"] = "no grain-grain contacts in this set";
    return j;
  }
  j["phi"] = matrix_json(f.phi);
  j["D2"] = matrix_json(f.density.D2);
  j["D4"] = tensor4_json(f.density.D4);
  j["principal_values"] = {f.principal.values[0], f.principal.values[1], f.principal.values[2]};
  j["principal_directions"] = matrix_json(f.principal.directions);
  j["psi"] = f.psi;
  const std::size_t n = f.normals.size(), m = std::min(n, std::max<std::size_t>(1, max_normals));
  nlohmann::json list = nlohmann::json::array();
  for (std::size_t i = 0; i < m; ++i) {
    const Vec3& v = f.normals[i * n / m];  // i n / m: evenly spread over the list
    list.push_back({v.x(), v.y(), v.z()});
  }
  j["normals"] = std::move(list);
  j["normals_subsampled"] = m < n;
  j["normals_total"] = n;
  j["normals_written"] = m;
  j["rose"] = {{"z_edges", f.rose.z_edges},
               {"azimuth_edges_rad", f.rose.azimuth_edges},
               {"density_per_sr", grid_json(f.rose.density, f.rose.z_edges.empty() ? 0 : f.rose.z_edges.size() - 1)}};
  j["kanatani_grid"] = {{"theta_rad", f.kanatani_grid.theta},
                        {"phi_rad", f.kanatani_grid.phi},
                        {"density_per_sr", grid_json(f.kanatani_grid.density, f.kanatani_grid.theta.size())}};
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
  fabric["all"] = fabric_json(analysis::fabric_result(now));
  if (b.band.found && analysis::mask_count(b.mask) > 0) {
    fabric["band"] = fabric_json(analysis::fabric_result(now, &b.mask));
  } else {
    fabric["band"] = {{"contacts", 0}, {"note", "no shear band found"}};
  }
  fabric["band"]["low_m"] = b.band.found ? nlohmann::json(b.band.z_low) : nlohmann::json(nullptr);
  fabric["band"]["high_m"] = b.band.found ? nlohmann::json(b.band.z_high) : nlohmann::json(nullptr);
  fabric["note"] = "unit normals of grain-grain contacts (sign-free); band: the contacts of the grains whose "
                   "reference centre is in the band, each once per such grain (as CN_S counts them)";
  write_json_file(dir / "fabric.json", fabric);
  write_file_atomically(dir / "force_chains.csv", force_chains_csv(analysis::force_segments(now)));
  write_file_atomically(dir / "derived.csv", derived_csv(test));
}

}  // namespace grainlab
