// The shear band of a shear test from plain inputs (no test type): the
// binning of the displacement profile and the rule for when a band counts.
//
// The horizontal displacement since the start of shear (along x) is binned by
// reference height into layers about one mean grain diameter thick between
// the floor (z = 0) and the cap height at the start of shear: thinner layers
// hold too few grains to give a mean, and a fixed range keeps the binning the
// same at every sample. The band is find_shear_band (shear_band.h) of that
// profile, and is only taken once the two plateaus differ by at least 10 % of
// the box displacement d_h = shear strain x box length (before that, e.g. at
// strain 0, the profile is elastic noise). Grains in the band: those whose
// reference centre lies in [z_low, z_high]. Heights are world-frame reference
// heights (m), floor at z = 0.
#pragma once

#include "analysis/grain_mask.h"
#include "analysis/shear_band.h"
#include "dynamics/state.h"

namespace grainlab::analysis {

// What the band rules need to know of the test.
struct BandInputs {
  double floor_height = 0;         // m, bottom of the specimen
  double cap_height_at_start = 0;  // m, cap height at the start of shear
  double mean_diameter = 0;        // m, layer thickness target
  double shear_strain = 0;         // d_h / L (-)
  double box_length = 0;           // m, L along the shear
  Vec3 shear_direction = Vec3::UnitX();  // the imposed displacement's direction
};

// Plateau difference required for a band, as a fraction of d_h.
inline constexpr double kBandJumpFraction = 0.1;

struct BandResult {
  ProfileSpec profile_spec;         // the binning used
  DisplacementProfile profile;
  ShearBand band;                   // band.found false: no band (yet)
  GrainMask mask;                   // grains in the band (by reference height); all 0 without a band
  double min_jump = 0;              // m, plateau difference required for a band
};

// The profile and band of `now` against the reference `ref` (rules above).
BandResult band_result(const State& now, const State& ref, const BandInputs& in);

}  // namespace grainlab::analysis
