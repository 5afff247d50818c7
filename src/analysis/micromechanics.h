// The end-of-run micromechanics summary of a specimen (run.json):
//  * mean Wadell roundness of the grains (geometry/shape_metrics.h on each
//    distinct shape once, weighted by the number of grains using it; spheres
//    count 1). Cost: one shape_metrics per library shape, not per grain
//    (measured on one core: 24 shapes of 500 faces, 0.03 s angular to 0.08 s
//    sub-angular), so it is computed at the end of every run;
//  * the peaks of the fabric factor Psi over the recorded series (largest
//    finite value, peak.h; NaN rows, before a contact exists, are skipped);
//  * the normal contact force statistics of the final contacts (force_stats.h);
//  * the Love-Weber stress of the final contacts (stress.h, wall contacts
//    included) over the specimen volume V = box length x box width x cap height.
#pragma once

#include "analysis/force_stats.h"
#include "analysis/peak.h"
#include "analysis/stress.h"
#include "dynamics/model.h"
#include "dynamics/state.h"

#include <optional>
#include <span>

namespace grainlab::analysis {

// Mean Wadell roundness over the grains (rules above); nullopt when there are
// no grains or a shape cannot be measured.
std::optional<double> mean_grain_roundness(const Model& model);

struct MicromechanicsSummary {
  std::optional<double> mean_roundness;
  std::optional<double> peak_fabric_psi, peak_fabric_psi_band;
  double specimen_volume = 0;       // m^3
  StressTensor love_weber;          // Pa, compression positive
  ForceStats forces;                // normal contact forces (N)
};

// The summary of the final `state` of `model` in a specimen of volume
// specimen_volume (m^3, the Love-Weber stress is averaged over it), with the
// recorded Psi series (either may be empty).
MicromechanicsSummary micromechanics_summary(const Model& model, const State& state, double specimen_volume,
                                             std::span<const double> fabric_psi,
                                             std::span<const double> fabric_psi_band);

}  // namespace grainlab::analysis
