// The micromechanics a shear test records at every sample (paper section 5):
// rotation, coordination and fabric of all grains and of the band, and the
// band limits, as pure functions of the current State, the shear reference
// (the grains at the start of shear) and the band inputs (band_analysis.h).
//
//   rotation_mean_deg          mean rotation since the start of shear, all grains (deg, Eq. 21)
//   rotation_band_deg          the same over the grains in the band (deg)
//   coordination_number_band   CN_S over the grains in the band (coordination.h)
//   fabric_psi                 octahedral fabric factor of all grain-grain contact normals (Eq. 29)
//   fabric_psi_band            the same over the contacts of the grains in the band
//   band_low_m, band_high_m    band limits (m)
// NaN where undefined: everything before shear (the reference does not hold
// the same grains), the band entries while there is no band, Psi without
// contacts. Cost: O(grains + contacts).
#pragma once

#include "analysis/band_analysis.h"
#include "dynamics/state.h"

namespace grainlab::analysis {

struct ShearSample {
  double rotation_mean_deg, rotation_band_deg, coordination_number_band;
  double fabric_psi, fabric_psi_band, band_low_m, band_high_m;
};

// The sample of `now` against `ref` (rules above).
ShearSample shear_sample(const State& now, const State& ref, const BandInputs& in);

}  // namespace grainlab::analysis
