// The contact laws' parameters in the config file: each law's own table
// [material.<law>] and the flat [material] keys of the same names read the
// same values (old configs keep parsing to the same spec), validation
// messages come from the law's rule with the file, key and line, and
// config.toml (to_toml) keeps the flat form byte for byte.
#include "core/error.h"
#include "dynamics/laws/registry.h"
#include "io/config.h"
#include "io_test_helpers.h"

#include <gtest/gtest.h>

#include <string>

namespace grainlab {
namespace {

using test::error_of;

std::string law_parse_error(const std::string& text) {
  return error_of<InputError>([&] { parse_config(text, "law.toml"); });
}

using test::has;

TEST(LawConfig, LawTablesAndFlatKeysGiveTheSameSpec) {
  const LabSpec flat = parse_config(
      "[material]\ncontact_law = \"hertz\"\nyoungs_modulus = 7e9\nrestitution = 0.8\nk_n = 3e11\ngamma_t = 15\n",
      "flat.toml");
  const LabSpec tables = parse_config(
      "[material]\ncontact_law = \"hertz\"\n\n[material.hertz]\nk_n = 3e11\ngamma_t = 15\n\n"
      "[material.hertz-material]\nyoungs_modulus = 7e9\nrestitution = 0.8\n",
      "tables.toml");
  EXPECT_TRUE(config_differences(flat, tables).empty());
  test::expect_same_spec(flat, tables);
  EXPECT_EQ(tables.material.grain.k_n, 3e11);
  EXPECT_EQ(tables.material.grain.gamma_t, 15);
  EXPECT_EQ(tables.material.grain.youngs_modulus, 7e9);
  EXPECT_EQ(tables.material.grain.restitution, 0.8);
  EXPECT_EQ(tables.material.grain.k_t, LabSpec{}.material.grain.k_t);
  // Hooke and Hertz share k_n (the one flat key), so its table sets it too.
  EXPECT_EQ(parse_config("[material.hooke]\nk_n = 5e5\n", "h.toml").material.grain.k_n, 5e5);
}

TEST(LawConfig, ConfigTomlKeepsTheFlatKeys) {
  EXPECT_TRUE(has(to_toml(LabSpec{}),
                  "[material]\npreset = \"\"\ncontact_law = \"hertz-material\"\ndensity = 2650.0\nfriction = 0.19\n"
                  "youngs_modulus = 4e9\npoisson_ratio = 0.3\nrestitution = 0.5\nk_n = 1e12\nk_t = 8e11\n"
                  "gamma_n = 40.0\ngamma_t = 20.0\nwall_friction = 0.0\n\n[box]\n"))
      << to_toml(LabSpec{});
}

TEST(LawConfig, DefaultConfigShowsTheChosenLawsTable) {
  const std::string text = default_config_toml();
  EXPECT_TRUE(has(text, "\n[material.hertz-material]\nyoungs_modulus = 4e9 ")) << text;
  EXPECT_TRUE(has(text, "# Pa, Young's modulus, > 0")) << text;
  EXPECT_FALSE(has(text, "k_n =")) << "only the chosen law's parameters";
  EXPECT_TRUE(has(text, "\"hooke\" (linear spring-dashpot: k_n (N/m)")) << text;
}

TEST(LawConfig, DefaultConfigOfAnotherLaw) {
  const std::string text = default_config_toml("direct-shear", contact_law<HookeLaw>());
  EXPECT_TRUE(has(text, "contact_law = \"hooke\"")) << text;
  EXPECT_TRUE(has(text, "\n[material.hooke]\nk_n = 1e12 ")) << text;
  EXPECT_TRUE(has(text, "# N/m, normal stiffness, > 0")) << text;
  EXPECT_FALSE(has(text, "youngs_modulus =")) << text;
  LabSpec hooke;
  hooke.material.law = contact_law<HookeLaw>();
  EXPECT_TRUE(config_differences(parse_config(text, "hooke.toml"), hooke).empty());
}

TEST(LawConfig, TheLawsRuleNamesKeyLineAndRange) {
  std::string msg = law_parse_error("[material.hertz-material]\nrestitution = 0\n");
  EXPECT_TRUE(has(msg, "law.toml (line 2): material.restitution = 0 is impossible: it must be in (0, 1]")) << msg;
  msg = law_parse_error("[material]\ncontact_law = \"hooke\"\n[material.hooke]\nk_t = -3\n");
  EXPECT_TRUE(has(msg, "law.toml (line 4): material.k_t = -3 is impossible: it must be >= 0 (N/m)")) << msg;
}

TEST(LawConfig, BadLawTablesAreRefused) {
  std::string msg = law_parse_error("[material.mindlin]\nk_n = 1\n");
  EXPECT_TRUE(has(msg, "unknown table [material.mindlin]")) << msg;
  EXPECT_TRUE(has(msg, "\"hertz-material\"")) << msg;
  msg = law_parse_error("[material.hooke]\nyoungs_modulus = 1e9\n");
  EXPECT_TRUE(has(msg, "law.toml (line 2): unknown key 'youngs_modulus' in [material.hooke]")) << msg;
  EXPECT_TRUE(has(msg, "k_n, k_t, gamma_n, gamma_t")) << msg;
  msg = law_parse_error("[material]\nk_n = 1e9\n[material.hertz]\nk_n = 2e9\n");
  EXPECT_TRUE(has(msg, "law.toml (line 4): material.k_n is given twice (also on line 2)")) << msg;
  msg = law_parse_error("[material]\ncontact_law = \"hooke\"\n[material.hooke]\nk_n = \"stiff\"\n");
  EXPECT_TRUE(has(msg, "law.toml (line 4): material.k_n expects a number")) << msg;
}

}  // namespace
}  // namespace grainlab
