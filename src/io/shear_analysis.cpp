// The analysis columns of a direct shear run (definitions in shear_analysis.h).
#include "io/shear_analysis.h"

#include "analysis/shear_sample.h"

namespace grainlab {

State shear_reference_state(const LabTest& test) {
  State ref;
  ref.bodies = test.reference();
  return ref;
}

analysis::BandInputs band_inputs(const LabTest& test) {
  const std::optional<BandGeometry> own = test.band_geometry();
  const BandGeometry g = own ? *own : whole_specimen_band_geometry(test.world());
  return {g.z_min, g.z_max, g.layer, g.strain, g.length, g.direction};
}

BandAnalysis analyse_band(const LabTest& test, const State& reference) {
  return analysis::band_result(test.world().state, reference, band_inputs(test));
}

const std::vector<std::string>& shear_analysis_columns() {
  static const std::vector<std::string> columns = {"rotation_mean_deg", "rotation_band_deg",
                                                   "coordination_number_band", "fabric_psi",
                                                   "fabric_psi_band", "band_low_m", "band_high_m"};
  return columns;
}

std::vector<double> shear_analysis_values(const LabTest& test) {
  const analysis::ShearSample s =
      analysis::shear_sample(test.world().state, shear_reference_state(test), band_inputs(test));
  return {s.rotation_mean_deg, s.rotation_band_deg, s.coordination_number_band, s.fabric_psi,
          s.fabric_psi_band,   s.band_low_m,        s.band_high_m};
}

void observe_shear_analysis(LabTest& test) {
  test.set_sample_observer(shear_analysis_columns(), [](const LabTest& t) { return shear_analysis_values(t); });
}

}  // namespace grainlab
