// The triaxial test's config table [triaxial]: its keys and their checks.
#include "lab/triaxial.h"

namespace grainlab {

LabTestKeys TriaxialTest::keys() {
  LabTestKeys k;
  k.table = {"triaxial",
             "drained triaxial compression: all five walls servo-held at consolidation.normal_stress (sigma_3), then "
             "the cap moves down"};
  k.fields = {
      {"triaxial", "final_strain", "axial strain (H_0 - H)/H_0 at which the test ends, in (0, 0.5]",
       [](LabSpec& s) -> SpecFieldRef { return &s.settings<TriaxialSpec>().final_strain; }},
  };
  k.validate = [](LabSpec& s, const SpecNeed& need) {
    TriaxialSpec& t = s.settings<TriaxialSpec>();
    need(t.final_strain > 0 && t.final_strain <= 0.5, "triaxial.final_strain", &t.final_strain,
         "in (0, 0.5] (axial strain: 15 % is 0.15)");
  };
  k.final_strain_key = "triaxial.final_strain";
  return k;
}

}  // namespace grainlab
