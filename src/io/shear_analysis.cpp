// The analysis columns of a direct shear run (definitions in shear_analysis.h).
#include "io/shear_analysis.h"

#include "analysis/coordination.h"
#include "analysis/fabric.h"
#include "analysis/rotation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace grainlab {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kDeg = 180.0 / std::numbers::pi;
constexpr double kBandJump = 0.1;  // plateau difference required, as a fraction of the box displacement d_h

// Psi of the contact normals (of the grains in mask, if given); NaN without contacts.
double fabric_psi(const State& s, const analysis::GrainMask* mask) {
  const std::vector<Vec3> normals = analysis::contact_normals(s, mask);
  if (normals.empty()) return kNaN;
  return analysis::octahedral_fabric_factor(analysis::fabric_tensors(normals).phi);
}

}  // namespace

State shear_reference_state(const LabTest& test) {
  State ref;
  ref.bodies = test.reference();
  return ref;
}

BandAnalysis analyse_band(const LabTest& test, const State& reference) {
  const State& now = test.world().state;
  BandAnalysis b;
  // Floor to the cap at the start of shear (before shear: now).
  const BandGeometry g = test.band_geometry();
  b.profile_spec.z_min = g.z_min;
  b.profile_spec.z_max = g.z_max;
  b.profile_spec.layers = std::max(1, static_cast<int>(std::lround(g.z_max / g.layer)));
  b.profile_spec.shear_direction = g.direction;
  b.profile = analysis::displacement_profile(now, reference, b.profile_spec);
  analysis::BandSpec spec;
  b.min_jump = std::max(spec.min_jump, kBandJump * g.strain * g.length);
  spec.min_jump = b.min_jump;
  b.band = analysis::find_shear_band(b.profile, spec);
  b.mask = analysis::grains_in_band(reference, b.band);
  return b;
}

const std::vector<std::string>& shear_analysis_columns() {
  static const std::vector<std::string> columns = {"rotation_mean_deg", "rotation_band_deg",
                                                   "coordination_number_band", "fabric_psi",
                                                   "fabric_psi_band", "band_low_m", "band_high_m"};
  return columns;
}

std::vector<double> shear_analysis_values(const LabTest& test) {
  const State& now = test.world().state;
  const State ref = shear_reference_state(test);
  if (ref.bodies.size() != now.bodies.size())  // not shearing yet: nothing to measure from
    return std::vector<double>(shear_analysis_columns().size(), kNaN);
  const BandAnalysis b = analyse_band(test, ref);
  const bool band = b.band.found && analysis::mask_count(b.mask) > 0;
  const analysis::GrainMask* mask = band ? &b.mask : nullptr;
  return {
      analysis::mean_rotation_angle(now, ref) * kDeg,
      band ? analysis::mean_rotation_angle(now, ref, mask) * kDeg : kNaN,
      band ? analysis::coordination_number(now, mask) : kNaN,
      fabric_psi(now, nullptr),
      band ? fabric_psi(now, mask) : kNaN,
      b.band.found ? b.band.z_low : kNaN,
      b.band.found ? b.band.z_high : kNaN,
  };
}

void observe_shear_analysis(LabTest& test) {
  test.set_sample_observer(shear_analysis_columns(), [](const LabTest& t) { return shear_analysis_values(t); });
}

}  // namespace grainlab
