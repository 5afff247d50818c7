// The micromechanics entries of run.json (scripts/report.py reads them),
// serialised from analysis/micromechanics.h:
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
//            normal contact force statistics (analysis/force_stats.h).
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

}  // namespace grainlab
