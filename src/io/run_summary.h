// The analysis entries of run.json (grainlab.report reads them): the micromechanics ones
// serialised from analysis/micromechanics.h,
//   "mean_roundness"               mean Wadell roundness of the grains (each
//                                  grain its shape's; spheres count 1)
//   "peaks": {"fabric_psi", "fabric_psi_band"}  largest values of those series
//   "final": {"cap_normal_stress_Pa", "love_weber_stress_Pa" (3x3, compression
//            positive), "love_weber_mean_Pa", "love_weber_deviatoric_Pa",
//            "love_weber_asymmetry", "specimen_volume_m3", "contacts",
//            "contact_force_mean_N", "contact_force_max_N",
//            "contact_force_std_N", "strong_contact_fraction"}: the Love-Weber
//            stress of the final contacts (analysis/stress.h, wall contacts
//            included) over the specimen volume = box area x cap height, next
//            to the stress the cap measures, for comparison; and the
//            normal contact force statistics (analysis/force_stats.h);
// and the peak rule's verdicts (analysis/peak.h) on the test's own peaks:
//   "peaks": {"friction_is_peak", "dilation_is_peak"}  false where
//            peaks.strain_at_peak_friction (strain_at_peak_dilation) lies in
//            the last 5 % of the series' shear_strain: a largest value there
//            is no peak reached (the curve may still be rising).
#pragma once

#include "dynamics/model.h"
#include "lab/lab_test.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace grainlab {

// The named column of the test's series (empty if it has none).
std::vector<double> series_column(const LabTest& test, const std::string& name);

// Adds the entries above to a run.json object (creating "peaks" and "final"
// if needed; existing keys there are kept).
void add_micromechanics_summary(nlohmann::json& run_json, const LabTest& test);

// Adds the verdicts above where run_json's "peaks" has the strain of a peak
// and the series has a shear_strain column (a direct shear run).
void add_peak_verdicts(nlohmann::json& run_json, const LabTest& test);

}  // namespace grainlab
