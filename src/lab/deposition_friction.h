// The deposition friction a specimen preparation starts from when the
// config leaves it to the preparation search (specimen.deposition_friction
// = -1, the default): each synthetic grain class carries the friction
// measured to prepare it at a known Dr on its own index void ratios in the
// default box (8.5 x 8.5 x 5.1 mm, 100 kPa, the default material and seed),
// and the search (lab/preparation_search.h) tries that friction first when
// the target is that Dr within the target's tolerance. Otherwise, and for
// imported or scanned grains, the first friction comes from the own
// indices: e linear in u = mu / (mu + 0.1) between e_min (u = 0) and e_max
// (u at the e_max preparation's friction, kLoosestDepositionFriction),
// inverted at the target e and kept within 5-95 % of that range; without
// indices (a void-ratio or lab-index target) 0.12.
//
// Measured in the default box with the default keys but grains.preset
// (`grainlab run`, one thread; docs/direct_shear.md, "Deposition friction
// of each grain class"):
//   glass-beads  0.012 -> Dr 0.89 (2026-12-06; the rounded grains' 0.032
//                gave 0.81 in the direct shear box, 0.84 in the closed box)
//   rounded      0.032 -> Dr 0.92 (the demo, 2026-12-04; the search landed
//                at 0.0319, Dr 0.93)
//   sub-angular  0.04  -> Dr 0.90 (the demo's grains until 2026-12-04)
//   angular      none measured: the search starts from the indices.
#pragma once

#include "lab/lab_spec.h"

#include <optional>

namespace grainlab {

// specimen.deposition_friction: chosen by the preparation search.
inline constexpr double kSearchedDepositionFriction = -1;

// A grain class's measured preparation: deposition at `friction` gave Dr
// `relative_density` on the class's own indices.
struct ClassDepositionFriction {
  double friction;
  double relative_density;
};

// The class's measured preparation (generated grains of grains.preset);
// nullopt for imported or scanned grains and for a class not measured.
std::optional<ClassDepositionFriction> class_deposition_friction(const GrainsSpec& grains);

// The friction the search tries first for spec's target (above). Ignores
// spec.specimen.deposition_friction.
double first_deposition_friction(const LabSpec& spec);

// spec.specimen.deposition_friction when it is given (>= 0), else
// first_deposition_friction: what a test built without the search
// (make_lab_test directly) deposits with.
double deposition_friction_of(const LabSpec& spec);

}  // namespace grainlab
