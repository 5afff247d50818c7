// run.json micromechanics entries (see run_summary.h).
#include "io/run_summary.h"

#include "analysis/micromechanics.h"
#include "analysis/peak.h"

namespace grainlab {

std::vector<double> series_column(const LabTest& test, const std::string& name) {
  const std::vector<std::string> columns = test.series_columns();
  std::vector<double> out;
  for (std::size_t c = 0; c < columns.size(); ++c) {
    if (columns[c] != name) continue;
    for (const auto& row : test.series()) out.push_back(row[c]);
  }
  return out;
}

void add_micromechanics_summary(nlohmann::json& j, const LabTest& test) {
  const World& w = test.world();
  const analysis::MicromechanicsSummary m = analysis::micromechanics_summary(
      w.model, w.state, test.specimen_volume(),
      series_column(test, "fabric_psi"), series_column(test, "fabric_psi_band"));
  if (m.mean_roundness) j["mean_roundness"] = *m.mean_roundness;
  if (m.peak_fabric_psi) j["peaks"]["fabric_psi"] = *m.peak_fabric_psi;
  if (m.peak_fabric_psi_band) j["peaks"]["fabric_psi_band"] = *m.peak_fabric_psi_band;
  const analysis::StressTensor& s = m.love_weber;
  nlohmann::json sigma = nlohmann::json::array();
  for (int i = 0; i < 3; ++i) sigma.push_back({s.sigma(i, 0), s.sigma(i, 1), s.sigma(i, 2)});
  nlohmann::json& f = j["final"];
  f["cap_normal_stress_Pa"] = test.boundary_stress();
  f["love_weber_stress_Pa"] = std::move(sigma);
  f["love_weber_mean_Pa"] = s.mean;
  f["love_weber_deviatoric_Pa"] = s.deviatoric;
  f["love_weber_asymmetry"] = s.asymmetry;
  f["specimen_volume_m3"] = m.specimen_volume;
  f["contacts"] = m.forces.contacts;
  f["contact_force_mean_N"] = m.forces.mean;
  f["contact_force_max_N"] = m.forces.max;
  f["contact_force_std_N"] = m.forces.std_dev;
  f["strong_contact_fraction"] = m.forces.strong_fraction;
}

void add_peak_verdicts(nlohmann::json& j, const LabTest& test) {
  const std::optional<double> end = analysis::series_peak(series_column(test, "shear_strain"));
  if (!end || !j.contains("peaks")) return;
  nlohmann::json& peaks = j["peaks"];
  for (const char* what : {"friction", "dilation"}) {
    const std::string at = std::string("strain_at_peak_") + what;
    if (peaks.contains(at) && peaks[at].is_number())
      peaks[std::string(what) + "_is_peak"] = analysis::is_peak_at(peaks[at].get<double>(), *end);
  }
}

}  // namespace grainlab
