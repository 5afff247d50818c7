// Presets for the four sands of the paper (He, Zheng and Schaefer 2021,
// Table 1 and section 3): contact coefficients, friction, Poisson ratio, the
// index void ratios and target relative density of the laboratory specimens,
// and the synthetic grain shape class that stands for each sand.
#pragma once

#include "lab/lab_spec.h"

#include <string>
#include <vector>

namespace grainlab {

// Names of the sand presets: crushed-limestone, griffin, ottawa, glass-beads.
std::vector<std::string> sand_preset_names();

// Overwrites the material, index void ratios, target Dr and grain shape preset
// of `spec` with the named sand's values; sets spec.material.preset = name.
// Throws InputError listing the valid names for an unknown name.
void apply_sand_preset(LabSpec& spec, const std::string& name);

}  // namespace grainlab
