// The first deposition friction of a preparation (see deposition_friction.h).
#include "lab/deposition_friction.h"

#include "lab/preparation_search.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string_view>

namespace grainlab {

namespace {

struct ClassEntry {
  std::string_view preset;
  ClassDepositionFriction measured;
};

constexpr std::array<ClassEntry, 3> kMeasured{{
    {"glass-beads", {0.012, 0.89}},
    {"rounded", {0.032, 0.92}},
    {"sub-angular", {0.04, 0.90}},
}};

constexpr double kU = 0.1;  // u = mu / (mu + kU), as the search interpolates

}  // namespace

std::optional<ClassDepositionFriction> class_deposition_friction(const GrainsSpec& grains) {
  if (!grains.folder.empty() || !grains.scan.empty()) return std::nullopt;
  for (const ClassEntry& c : kMeasured)
    if (c.preset == grains.preset) return c.measured;
  return std::nullopt;
}

double first_deposition_friction(const LabSpec& spec) {
  const auto& s = spec.specimen;
  if (const auto measured = class_deposition_friction(spec.grains);
      measured && spec.targets_own_indices() &&
      std::abs(s.relative_density - measured->relative_density) <= s.relative_density_tolerance)
    return measured->friction;
  if (!spec.own_indices_known()) return 0.12;
  const double u_index = kLoosestDepositionFriction / (kLoosestDepositionFriction + kU);
  const double f = (spec.target_void_ratio() - s.own_e_min) / (s.own_e_max - s.own_e_min);
  const double u = std::clamp(f, 0.05, 0.95) * u_index;
  return kU * u / (1 - u);
}

double deposition_friction_of(const LabSpec& spec) {
  return spec.specimen.deposition_friction >= 0 ? spec.specimen.deposition_friction : first_deposition_friction(spec);
}

}  // namespace grainlab
