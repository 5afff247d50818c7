// The paper's four sands. Common to all (Table 1): density 2650 kg/m^3,
// E = 4e9 Pa, k_n = 1e12, k_t = 8e11, gamma_n = 40, gamma_t = 20. Friction and
// Poisson ratio per sand from Table 1; e_max, e_min and the specimens' Dr from
// section 3. Restitution and the contact law are left as they are: the paper
// gives no restitution, and the law is the user's choice.
#include "lab/sand_presets.h"

#include "core/error.h"

#include <array>
#include <string_view>

namespace grainlab {
namespace {

struct SandPreset {
  std::string_view name;
  double friction;
  double poisson_ratio;
  double e_max, e_min;
  double relative_density;
  std::string_view grain_shape;  // synthetic grain class that stands for the sand
};

constexpr std::array<SandPreset, 4> kSands{{
    {"crushed-limestone", 0.28, 0.25, 1.08, 0.56, 0.96, "angular"},
    {"griffin", 0.19, 0.30, 0.86, 0.53, 0.97, "sub-angular"},
    {"ottawa", 0.19, 0.30, 0.75, 0.52, 0.96, "rounded"},
    {"glass-beads", 0.12, 0.30, 0.75, 0.50, 0.96, "glass-beads"},
}};

}  // namespace

std::vector<std::string> sand_preset_names() {
  std::vector<std::string> names;
  for (const SandPreset& s : kSands) names.emplace_back(s.name);
  return names;
}

void apply_sand_preset(LabSpec& spec, const std::string& name) {
  for (const SandPreset& s : kSands) {
    if (s.name != name) continue;
    spec.material.preset = name;
    Material& m = spec.material.grain;
    m.density = 2650;
    m.youngs_modulus = 4e9;
    m.k_n = 1e12;
    m.k_t = 8e11;
    m.gamma_n = 40;
    m.gamma_t = 20;
    m.friction = s.friction;
    m.poisson_ratio = s.poisson_ratio;
    spec.specimen.e_max = s.e_max;
    spec.specimen.e_min = s.e_min;
    spec.specimen.relative_density = s.relative_density;
    spec.grains.preset = std::string(s.grain_shape);
    return;
  }
  input_error("unknown sand preset '{}': use one of crushed-limestone, griffin, ottawa, glass-beads "
              "(the paper's four sands), or leave material.preset out and give the values yourself",
              name);
}

}  // namespace grainlab
