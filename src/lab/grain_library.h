// Puts the grain shapes a run asks for into a Model.
#pragma once

#include "dynamics/model.h"
#include "lab/direct_shear_spec.h"

#include <vector>

namespace grainlab {

// Adds spec.shapes grain shapes (generated from the preset, or imported from
// the folder) at their physical size to `model`, and returns their indices.
// Glass beads become analytic spheres.
std::vector<Index> add_grain_shapes(Model& model, const GrainsSpec& spec, std::uint64_t seed);

}  // namespace grainlab
