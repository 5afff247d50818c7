// The shear band from plain inputs (rules in band_analysis.h).
#include "analysis/band_analysis.h"

#include <algorithm>
#include <cmath>

namespace grainlab::analysis {

BandResult band_result(const State& now, const State& ref, const BandInputs& in) {
  BandResult b;
  b.profile_spec.z_min = in.floor_height;
  b.profile_spec.z_max = in.cap_height_at_start;
  const double height = in.cap_height_at_start - in.floor_height;
  b.profile_spec.layers = std::max(1, static_cast<int>(std::lround(height / in.mean_diameter)));
  b.profile_spec.shear_direction = in.shear_direction;
  b.profile = displacement_profile(now, ref, b.profile_spec);
  BandSpec spec;
  b.min_jump = std::max(spec.min_jump, kBandJumpFraction * in.shear_strain * in.box_length);
  spec.min_jump = b.min_jump;
  b.band = find_shear_band(b.profile, spec);
  b.mask = grains_in_band(ref, b.band);
  return b;
}

}  // namespace grainlab::analysis
