// The four sand presets carry the paper's Table 1 and section 3 values.
#include "lab/sand_presets.h"

#include "core/error.h"

#include <gtest/gtest.h>

namespace grainlab {
namespace {

TEST(SandPresets, NamesAreThePapersFourSands) {
  EXPECT_EQ(sand_preset_names(),
            (std::vector<std::string>{"crushed-limestone", "griffin", "ottawa", "glass-beads"}));
}

TEST(SandPresets, CommonTable1Values) {
  for (const std::string& name : sand_preset_names()) {
    LabSpec spec;
    apply_sand_preset(spec, name);
    const Material& m = spec.material.grain;
    EXPECT_EQ(spec.material.preset, name);
    EXPECT_EQ(m.density, 2650);
    EXPECT_EQ(m.youngs_modulus, 4e9);
    EXPECT_EQ(m.k_n, 1e12);
    EXPECT_EQ(m.k_t, 8e11);
    EXPECT_EQ(m.gamma_n, 40);
    EXPECT_EQ(m.gamma_t, 20);
  }
}

TEST(SandPresets, PerSandValues) {
  struct Expect {
    const char* name;
    double friction, poisson, e_max, e_min, dr;
    const char* shape;
  };
  const Expect expected[] = {
      {"crushed-limestone", 0.28, 0.25, 1.08, 0.56, 0.96, "angular"},
      {"griffin", 0.19, 0.3, 0.86, 0.53, 0.97, "sub-angular"},
      {"ottawa", 0.19, 0.3, 0.75, 0.52, 0.96, "rounded"},
      {"glass-beads", 0.12, 0.3, 0.75, 0.50, 0.96, "glass-beads"},
  };
  for (const Expect& e : expected) {
    SCOPED_TRACE(e.name);
    LabSpec spec;
    apply_sand_preset(spec, e.name);
    EXPECT_EQ(spec.material.grain.friction, e.friction);
    EXPECT_EQ(spec.material.grain.poisson_ratio, e.poisson);
    EXPECT_EQ(spec.specimen.e_max, e.e_max);
    EXPECT_EQ(spec.specimen.e_min, e.e_min);
    EXPECT_EQ(spec.specimen.relative_density, e.dr);
    EXPECT_EQ(spec.grains.preset, e.shape);
  }
}

TEST(SandPresets, LeavesOtherFieldsAlone) {
  LabSpec spec;
  spec.consolidation.normal_stress = 50e3;
  spec.material.grain.restitution = 0.7;
  spec.box.length = 0.03;
  apply_sand_preset(spec, "ottawa");
  EXPECT_EQ(spec.consolidation.normal_stress, 50e3);
  EXPECT_EQ(spec.material.grain.restitution, 0.7);
  EXPECT_EQ(spec.box.length, 0.03);
}

TEST(SandPresets, UnknownNameListsTheValidOnes) {
  LabSpec spec;
  try {
    apply_sand_preset(spec, "beach");
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("beach"), std::string::npos) << msg;
    for (const std::string& name : sand_preset_names())
      EXPECT_NE(msg.find(name), std::string::npos) << msg;
  }
}

}  // namespace
}  // namespace grainlab
