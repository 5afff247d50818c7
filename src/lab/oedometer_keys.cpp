// The oedometer's config table [oedometer]: its keys and their checks.
#include "lab/oedometer.h"

#include <algorithm>

namespace grainlab {

LabTestKeys OedometerTest::keys() {
  LabTestKeys k;
  k.table = {"oedometer",
             "one-dimensional compression in the box with its gap closed (a rigid ring): the loading schedule"};
  k.fields = {
      {"oedometer", "stresses",
       "Pa, the cap's stresses after consolidation, in order; one below the one before unloads",
       [](LabSpec& s) -> SpecFieldRef { return &s.settings<OedometerSpec>().stresses; }},
      {"oedometer", "loading",
       "\"stages\": each stress held to rest (incremental loading, ASTM D2435) | \"constant-rate\": the cap moves at "
       "a constant strain rate from numerics.inertial_number to each stress (ASTM D4186)",
       [](LabSpec& s) -> SpecFieldRef { return &s.settings<OedometerSpec>().loading; }},
  };
  k.validate = [](LabSpec& s, const SpecNeed& need) {
    OedometerSpec& o = s.settings<OedometerSpec>();
    need(!o.stresses.empty() && *std::min_element(o.stresses.begin(), o.stresses.end()) > 0, "oedometer.stresses",
         &o.stresses, "a list of at least one stress > 0 (Pa; e.g. [200e3, 400e3, 800e3, 200e3])");
    need(o.loading == "stages" || o.loading == "constant-rate", "oedometer.loading", &o.loading,
         "\"stages\" or \"constant-rate\"");
  };
  // (output.strain_interval is checked against shear.final_strain, as before the tests had their own tables.)
  k.final_strain_key = "shear.final_strain";
  return k;
}

}  // namespace grainlab
