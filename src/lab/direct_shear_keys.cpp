// The direct shear's config table [shear]: its keys and their checks.
#include "lab/direct_shear.h"

namespace grainlab {

LabTestKeys DirectShearTest::keys() {
  LabTestKeys k;
  k.table = {"shear", "shearing: the upper half moves along x"};
  k.fields = {
      {"shear", "speed", "m/s of the upper half; 0 = from numerics.inertial_number",
       [](LabSpec& s) -> SpecFieldRef { return &s.settings<ShearSpec>().speed; }},
      {"shear", "final_strain", "shear strain d_h / L at which the test ends, in (0, 1]",
       [](LabSpec& s) -> SpecFieldRef { return &s.settings<ShearSpec>().final_strain; }},
  };
  k.validate = [](LabSpec& s, const SpecNeed& need) {
    ShearSpec& sh = s.settings<ShearSpec>();
    need(sh.speed >= 0, "shear.speed", &sh.speed, ">= 0 (m/s; 0 picks it from numerics.inertial_number)");
    need(sh.final_strain > 0 && sh.final_strain <= 1, "shear.final_strain", &sh.final_strain,
         "in (0, 1] (a fraction: 10 % is 0.10)");
  };
  k.final_strain_key = "shear.final_strain";
  return k;
}

}  // namespace grainlab
