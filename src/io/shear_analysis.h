// The micromechanics of a direct shear test (paper section 5, issue 5), as
// the run records it: the analysis columns appended to every row of
// series.csv, and the shear band they rest on. Pure functions of the test's
// current State and its shear reference (LabTest::reference(),
// the grains at the start of shear), built from the analysis layer.
//
// Shear band. The horizontal displacement since the start of shear is binned
// by reference height into layers about one mean grain diameter thick
// between the floor (z = 0) and the cap at the start of shear (the test's
// LabTest::band_geometry()): thinner layers hold too few grains to give a mean, and
// a fixed range keeps the binning the same at every sample. The band is
// analysis::find_shear_band of that profile, and is only taken once the two
// plateaus differ by at least 10 % of the box displacement d_h (before that,
// e.g. at strain 0, the profile is elastic noise): NaN otherwise. Heights are
// world-frame reference heights (m), floor at z = 0. Grains in the band: those
// whose reference centre lies in [band_low_m, band_high_m].
//
// Columns (one value each per sample; NaN where undefined, e.g. no band yet):
//   rotation_mean_deg          mean rotation since the start of shear, all grains (deg, Eq. 21)
//   rotation_band_deg          the same over the grains in the band (deg)
//   coordination_number_band   CN_S over the grains in the band (analysis/coordination.h)
//   fabric_psi                 octahedral fabric factor of all grain-grain contact normals (Eq. 29)
//   fabric_psi_band            the same over the contacts of the grains in the band
//   band_low_m, band_high_m    band limits (m)
// Cost per sample: O(grains + contacts).
#pragma once

#include "analysis/grain_mask.h"
#include "analysis/shear_band.h"
#include "dynamics/state.h"
#include "lab/lab_test.h"

#include <string>
#include <vector>

namespace grainlab {

// The test's shear reference as a State (bodies only); empty before shear.
State shear_reference_state(const LabTest& test);

// The profile and band of the test's current state (rules above).
struct BandAnalysis {
  analysis::ProfileSpec profile_spec;   // the binning used
  analysis::DisplacementProfile profile;
  analysis::ShearBand band;             // band.found false: no band (yet)
  analysis::GrainMask mask;             // grains in the band (by reference height); all 0 without a band
  double min_jump = 0;                  // m, plateau difference required for a band
};
BandAnalysis analyse_band(const LabTest& test, const State& reference);

// The analysis columns, in order (names above).
const std::vector<std::string>& shear_analysis_columns();

// Their values for the test's current state (shear_analysis_columns() order).
std::vector<double> shear_analysis_values(const LabTest& test);

// Sets the test's sample observer to shear_analysis_values: call before the
// run starts (and the same on a resumed run, so that its rows match).
void observe_shear_analysis(LabTest& test);

}  // namespace grainlab
