// The SH sand presets (see sh_sands.h); their numbers are in sh_sand_models.cpp.
#include "grains/sh_sands.h"

namespace grainlab {

const std::vector<ShSand>& sh_sands() {
  static const std::vector<ShSand> sands = [] {
    using namespace sh_sand_data;
    std::vector<ShSand> s{
        {"sh-ottawa", "Ottawa sand (rounded natural quartz), from 16 CT-scanned grains of NIST VCCTL",
         ottawa_spectrum(), ottawa_means()},
        {"sh-river", "river sand (AASHTO MA113AB-2-fine, Patuxent River), from 16 CT-scanned grains of NIST VCCTL",
         river_spectrum(), river_means()},
        {"sh-limestone", "crushed limestone (VCCTL LS-coarse, 9.5-19 mm, scaled to the sieve range), from 16 "
                         "CT-scanned grains of NIST VCCTL",
         limestone_spectrum(), limestone_means()},
    };
    for (const ShSand& sand : s) validate(sand.spectrum);
    return s;
  }();
  return sands;
}

const ShSand* find_sh_sand(const std::string& name) {
  for (const ShSand& s : sh_sands()) {
    if (s.name == name) return &s;
  }
  return nullptr;
}

std::string sh_sand_names() { return "sh-ottawa, sh-river, sh-limestone"; }

}  // namespace grainlab
