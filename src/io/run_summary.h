// The micromechanics entries of run.json (scripts/report.py reads them):
//   "mean_roundness"               mean Wadell roundness of the grains (each
//                                  grain its shape's; spheres count 1)
//   "peaks": {"fabric_psi"}        largest fabric_psi of the series
//   "final": {"cap_normal_stress_Pa", "love_weber_stress_Pa" (3x3, compression
//            positive), "love_weber_mean_Pa", "love_weber_deviatoric_Pa",
//            "love_weber_asymmetry", "specimen_volume_m3"}: the Love-Weber
//            stress of the final contacts (analysis/stress.h, wall contacts
//            included) over the specimen volume = box area x cap height, next
//            to the stress the cap measures, for comparison.
#pragma once

#include "dynamics/model.h"
#include "lab/lab_test.h"

#include <nlohmann/json.hpp>

#include <optional>

namespace grainlab {

// Mean Wadell roundness over the grains (geometry/shape_metrics.h on each
// distinct shape once, weighted by the number of grains using it); nullopt
// when a shape cannot be measured. Cost: one shape_metrics per library shape,
// not per grain (measured on one core: 24 shapes of 500 faces, 0.03 s angular
// to 0.08 s sub-angular), so it is computed at the end of every run.
std::optional<double> mean_grain_roundness(const Model& model);

// Adds the entries above to a run.json object (creating "peaks" and "final"
// if needed; existing keys there are kept).
void add_micromechanics_summary(nlohmann::json& run_json, const LabTest& test);

}  // namespace grainlab
