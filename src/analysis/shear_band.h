// Horizontal grain displacement against height (paper Fig. 11) and the shear
// band found from it.
//
// Profile. Grains are binned by their reference height z_ref (m) into
// `layers` equal layers between z_min and z_max (by default the lowest and
// highest reference centres). Per layer: the mean displacement along the
// shear direction, u = (x_now - x_ref) . e (m), and the grain count.
//
// Band. In a direct shear test the lower box half holds its grains (u ~ 0) and
// the upper half carries its grains along (u ~ the box displacement); between
// them u(z) rises through the band. grainlab normalises the profile between
// its two plateaus,
//     U(z) = (u(z) - u_bottom) / (u_top - u_bottom),
// u_bottom and u_top being the medians of the lowest and the highest
// `plateau_fraction` of the non-empty layers (medians: a layer with a few
// dragged grains does not shift the plateau), and takes the band as the
// heights where U runs from `lower` to `upper` (0.1 and 0.9 by default) around
// the middle of the transition:
//  1. z_mid: the first height, scanning upward, where U crosses 1/2;
//  2. z_low: scanning down from z_mid, the first crossing of `lower`;
//  3. z_high: scanning up from z_mid, the first crossing of `upper`;
// each crossing located by linear interpolation between layer centres (empty
// layers are skipped). For a tanh profile u = (d/2)(1 + tanh((z - z0)/w)) this
// gives z0 -+ w atanh(0.8); for a linear ramp from z1 to z2 it gives
// z1 + 0.1 (z2 - z1) and z1 + 0.9 (z2 - z1). Scanning outward from the middle
// keeps noise in the plateaus from widening the band. No band is reported when
// |u_top - u_bottom| is below `min_jump` (nothing has been sheared).
#pragma once

#include "analysis/grain_mask.h"
#include "core/types.h"
#include "dynamics/state.h"

#include <vector>

namespace grainlab::analysis {

struct ProfileSpec {
  int layers = 20;
  double z_min = 0, z_max = 0;                // m; z_min >= z_max: from the reference heights
  Vec3 shear_direction = Vec3::UnitX();       // displacement component measured (normalised here)
};

struct DisplacementProfile {
  std::vector<double> z;      // layer centres (m)
  std::vector<double> u;      // mean displacement along the shear direction (m); NaN if empty
  std::vector<Index> count;   // grains in each layer
  double z_min = 0, z_max = 0;  // range binned (m)
};

// The profile of the displacements from `ref` to `now`, binned by reference height.
DisplacementProfile displacement_profile(const State& now, const State& ref, const ProfileSpec& spec = {});

struct BandSpec {
  double lower = 0.1, upper = 0.9;  // normalised displacement limits of the band
  double plateau_fraction = 0.2;    // share of the non-empty layers in each plateau (at least 1)
  double min_jump = 1e-9;           // m; |u_top - u_bottom| at or below it: no band (1 nm: flat to rounding)
};

struct ShearBand {
  bool found = false;
  double z_low = 0, z_high = 0;       // band limits (m)
  double z_mid = 0;                   // where U = 1/2 (m)
  double u_bottom = 0, u_top = 0;     // plateau displacements (m)
};

// The band of a profile (method above).
ShearBand find_shear_band(const DisplacementProfile& profile, const BandSpec& spec = {});

// Grains whose centre height in `s` lies in [z_low, z_high] (pass the
// reference State to select by reference height, the current one for the
// present height). An empty mask of the right size when no band was found.
GrainMask grains_in_band(const State& s, const ShearBand& band);

}  // namespace grainlab::analysis
