// The config file: defaults, round trip, presets, and the messages for every
// kind of bad input (they must name the file, the key and the line).
#include "dynamics/laws/registry.h"
#include "io/config.h"

#include "core/error.h"
#include "core/atomic_file.h"
#include "io/json.h"
#include "io_test_helpers.h"
#include "lab/sand_presets.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <fstream>
#include <random>
#include <sstream>

namespace grainlab {
namespace {

using test::error_of;
using test::expect_same_spec;

std::string parse_error(const std::string& text) {
  return error_of<InputError>([&] { parse_config(text, "test.toml"); });
}

using test::has;

TEST(Config, DefaultConfigParsesToTheDefaults) {
  const std::string text = default_config_toml();
  expect_same_spec(parse_config(text, "defaults.toml"), LabSpec{});
  EXPECT_TRUE(config_differences(parse_config(text, "defaults.toml"), LabSpec{}).empty());
}

TEST(Config, DefaultConfigNamesEveryKeyWithAComment) {
  const std::string text = default_config_toml();
  for (const char* key : {"seed =", "[grains]", "d_min =", "[material]", "contact_law =", "wall_friction =",
                          "[box]", "gap =", "[specimen]", "deposition_friction =", "[consolidation]",
                          "normal_stress =", "[shear]", "final_strain =", "[numerics]", "threads =", "[output]",
                          "checkpoint_interval =", "snapshot_interval ="})
    EXPECT_TRUE(has(text, key)) << key;
  // Every key line carries a comment.
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line))
    if (line.find(" = ") != std::string::npos) {
      EXPECT_TRUE(has(line, "# ")) << line;
    }
}

TEST(Config, OedometerDefaultsHaveTheScheduleAndNotTheShear) {
  const std::string text = default_config_toml("oedometer");
  EXPECT_TRUE(has(text, "test = \"oedometer\""));
  EXPECT_TRUE(has(text, "[oedometer]"));
  EXPECT_TRUE(has(text, "stresses = [200000.0, 400000.0, 800000.0, 400000.0, 200000.0, 100000.0]"));
  EXPECT_FALSE(has(text, "\n[shear]\n"));
  EXPECT_TRUE(has(default_config_toml(), "\n[shear]\n"));
  EXPECT_FALSE(has(default_config_toml(), "\n[oedometer]\n"));
  const LabSpec s = parse_config(text, "oedometer.toml");
  EXPECT_EQ(s.test, "oedometer");
  EXPECT_EQ(s.output.folder, "runs/oedometer");
  EXPECT_THROW(default_config_toml("simple-shear"), InputError);
  const std::string tx = default_config_toml("triaxial");
  EXPECT_TRUE(has(tx, "\n[triaxial]\nfinal_strain = 0.15"));
  EXPECT_FALSE(has(tx, "\n[oedometer]\n"));
}

TEST(Config, OedometerScheduleIsAListOfPositiveStresses) {
  const LabSpec s = parse_config("test = \"oedometer\"\n[oedometer]\nstresses = [50000, 1e5, 2.5e5]\n", "o.toml");
  EXPECT_EQ(s.settings<OedometerSpec>().stresses, (std::vector<double>{50e3, 100e3, 250e3}));
  std::string msg = parse_error("[oedometer]\nstresses = []\n");
  EXPECT_TRUE(has(msg, "oedometer.stresses = [] is impossible")) << msg;
  EXPECT_TRUE(has(msg, "line 2")) << msg;
  msg = parse_error("[oedometer]\nstresses = [1e5, -2e5]\n");
  EXPECT_TRUE(has(msg, "at least one stress > 0")) << msg;
  msg = parse_error("[oedometer]\nstresses = [1e5, \"200 kPa\"]\n");
  EXPECT_TRUE(has(msg, "a list of numbers in SI units")) << msg;
  EXPECT_TRUE(has(msg, "the string \"200 kPa\"")) << msg;
  msg = parse_error("[oedometer]\nstresses = 1e5\n");
  EXPECT_TRUE(has(msg, "expects a list of numbers")) << msg;
  msg = parse_error("[oedometer]\nstresses = [1e5, nan]\n");
  EXPECT_TRUE(has(msg, "a list of finite numbers")) << msg;
  EXPECT_EQ(s.settings<OedometerSpec>().loading, "stages");
  EXPECT_EQ(parse_config("[oedometer]\nloading = \"constant-rate\"\n", "o.toml").settings<OedometerSpec>().loading, "constant-rate");
  msg = parse_error("[oedometer]\nloading = \"fast\"\n");
  EXPECT_TRUE(has(msg, "oedometer.loading = \"fast\" is impossible")) << msg;
  EXPECT_TRUE(has(msg, "\"stages\" or \"constant-rate\"")) << msg;
  msg = parse_error("test = \"simple-shear\"\n");
  EXPECT_TRUE(has(msg, "test = \"simple-shear\" is impossible")) << msg;
  EXPECT_TRUE(has(msg, "\"direct-shear\", \"oedometer\", \"triaxial\"")) << msg;
  msg = parse_error("test = \"triaxial\"\n[triaxial]\nfinal_strain = 0.6\n");
  EXPECT_TRUE(has(msg, "triaxial.final_strain = 0.6 is impossible")) << msg;
  msg = parse_error("test = \"triaxial\"\n[triaxial]\nfinal_strain = 0.01\n[output]\nstrain_interval = 0.02\n");
  EXPECT_TRUE(has(msg, "at most triaxial.final_strain = 0.01")) << msg;
}

TEST(Config, EmptyFileGivesTheDefaults) { expect_same_spec(parse_config("", "empty.toml"), LabSpec{}); }

TEST(Config, ToTomlRoundTripsEveryField) {
  const LabSpec s = test::all_fields_changed();
  ASSERT_EQ(config_differences(s, LabSpec{}).size(), 55u) << "a field was left at its default";
  const LabSpec back = parse_config(to_toml(s), "roundtrip.toml");
  expect_same_spec(back, s);
  EXPECT_TRUE(config_differences(back, s).empty());
  EXPECT_EQ(to_toml(back), to_toml(s));
}

TEST(Config, ToTomlKeepsEveryDoubleExactly) {
  std::mt19937_64 rng(5);
  std::uniform_int_distribution<std::uint64_t> bits;
  for (int i = 0; i < 300; ++i) {
    LabSpec s;
    do s.numerics.density_scaling = std::fabs(std::bit_cast<double>(bits(rng)));
    while (!std::isfinite(s.numerics.density_scaling));
    if (i % 3 == 0) s.numerics.density_scaling = std::ldexp(s.numerics.density_scaling, -std::ilogb(s.numerics.density_scaling) + (i % 40) - 20);
    const LabSpec back = parse_config(to_toml(s), "r.toml");
    ASSERT_EQ(std::bit_cast<std::uint64_t>(back.numerics.density_scaling),
              std::bit_cast<std::uint64_t>(s.numerics.density_scaling))
        << to_toml(s);
  }
  EXPECT_TRUE(has(default_config_toml(), "youngs_modulus = 4e9 "));
  EXPECT_TRUE(has(default_config_toml(), "d_min = 7.07e-4 "));
}

TEST(Config, ToTomlRoundTripsAPreset) {
  LabSpec s;
  apply_sand_preset(s, "crushed-limestone");
  s.material.grain.friction = 0.4;  // explicit override of the preset
  expect_same_spec(parse_config(to_toml(s), "preset.toml"), s);
}

TEST(Config, PresetFirstThenExplicitKeysOverride) {
  const LabSpec s = parse_config(R"(
[material]
friction = 0.5
preset = "glass-beads"

[grains]
preset = "rounded"
)",
                                         "p.toml");
  EXPECT_EQ(s.material.preset, "glass-beads");
  EXPECT_EQ(s.material.grain.friction, 0.5);          // explicit key wins, whatever the order in the file
  EXPECT_EQ(s.material.grain.poisson_ratio, 0.3);     // from the preset
  EXPECT_EQ(s.specimen.e_max, 0.75);                  // from the preset
  EXPECT_EQ(s.specimen.e_min, 0.50);
  EXPECT_EQ(s.grains.preset, "rounded");              // explicit key wins
  const LabSpec t = parse_config("[material]\npreset = \"crushed-limestone\"\n", "p.toml");
  EXPECT_EQ(t.grains.preset, "angular");
  EXPECT_EQ(t.material.grain.friction, 0.28);
}

TEST(Config, SphericalHarmonicSandsAreGrainPresets) {
  for (const char* sand : {"sh-ottawa", "sh-river", "sh-limestone"}) {
    EXPECT_EQ(parse_config(fmt::format("[grains]\npreset = \"{}\"\n", sand), "sh.toml").grains.preset, sand);
  }
  EXPECT_EQ(LabSpec{}.grains.preset, "rounded");  // the default stays the polytope preset
}

TEST(Config, IntegersAreAcceptedForNumbers) {
  const LabSpec s = parse_config("[consolidation]\nnormal_stress = 50000\n[material]\ndensity = 2600\n", "i.toml");
  EXPECT_EQ(s.consolidation.normal_stress, 50000.0);
  EXPECT_EQ(s.material.grain.density, 2600.0);
}

TEST(Config, ContactLawNames) {
  EXPECT_EQ(parse_config("[material]\ncontact_law = \"hooke\"\n", "l.toml").material.law, contact_law<HookeLaw>());
  EXPECT_EQ(parse_config("[material]\ncontact_law = \"hertz\"\n", "l.toml").material.law, contact_law<HertzUserLaw>());
  const std::string msg = parse_error("[material]\ncontact_law = \"mindlin\"\n");
  EXPECT_TRUE(has(msg, "test.toml (line 2")) << msg;
  EXPECT_TRUE(has(msg, "material.contact_law")) << msg;
  EXPECT_TRUE(has(msg, "hertz-material")) << msg;
}

TEST(Config, SyntaxErrorNamesFileLineAndColumn) {
  const std::string msg = parse_error("seed = 3\n[box]\nlength = = 0.01\n");
  EXPECT_TRUE(has(msg, "test.toml (line 3, column")) << msg;
  EXPECT_TRUE(has(msg, "syntax")) << msg;
}

TEST(Config, UnknownKeySuggestsTheClosest) {
  const std::string msg = parse_error("[consolidation]\n\nnormal_stres = 1e5\n");
  EXPECT_TRUE(has(msg, "test.toml (line 3)")) << msg;
  EXPECT_TRUE(has(msg, "consolidation.normal_stres")) << msg;
  EXPECT_TRUE(has(msg, "Did you mean 'normal_stress'")) << msg;
}

TEST(Config, KeyInTheWrongPlace) {
  const std::string msg = parse_error("normal_stress = 1e5\n");
  EXPECT_TRUE(has(msg, "[consolidation]")) << msg;
  const std::string far = parse_error("[shear]\nzzzzzzzz = 1\n");
  EXPECT_FALSE(has(far, "Did you mean")) << far;
  EXPECT_TRUE(has(far, "speed, final_strain")) << far;
}

TEST(Config, UnknownTable) {
  const std::string msg = parse_error("[consolidaton]\nnormal_stress = 1e5\n");
  EXPECT_TRUE(has(msg, "unknown table [consolidaton]")) << msg;
  EXPECT_TRUE(has(msg, "Did you mean 'consolidation'")) << msg;
  EXPECT_TRUE(has(msg, "line 1")) << msg;
  const std::string nested = parse_error("[material.grain]\ndensity = 1\n");
  EXPECT_TRUE(has(nested, "material.grain")) << nested;
  const std::string not_table = parse_error("box = 3\n");
  EXPECT_TRUE(has(not_table, "'box' must be a table")) << not_table;
}

TEST(Config, WrongTypes) {
  const std::string msg = parse_error("[consolidation]\nnormal_stress = \"100 kPa\"\n");
  EXPECT_TRUE(has(msg, "test.toml (line 2)")) << msg;
  EXPECT_TRUE(has(msg, "consolidation.normal_stress expects a number")) << msg;
  EXPECT_TRUE(has(msg, "\"100 kPa\"")) << msg;
  EXPECT_TRUE(has(parse_error("[grains]\nfaces = 500.0\n"), "whole number"));
  EXPECT_TRUE(has(parse_error("[grains]\npreset = 3\n"), "string"));
  EXPECT_TRUE(has(parse_error("[box]\nlength = true\n"), "boolean"));
  EXPECT_TRUE(has(parse_error("seed = -1\n"), "seed"));
  EXPECT_TRUE(has(parse_error("[grains]\nshapes = 99999999999\n"), "out of range"));
}

struct BadValue {
  const char* text;
  const char* key;
};

class ConfigImpossible : public ::testing::TestWithParam<BadValue> {};

TEST_P(ConfigImpossible, NamesKeyLineAndRule) {
  const std::string msg = parse_error(GetParam().text);
  EXPECT_TRUE(has(msg, std::string(GetParam().key) + " = ")) << msg;
  EXPECT_TRUE(has(msg, "impossible: it must be")) << msg;
  EXPECT_TRUE(has(msg, "test.toml (line ")) << msg;
}

INSTANTIATE_TEST_SUITE_P(
    Values, ConfigImpossible,
    ::testing::Values(BadValue{"[consolidation]\nnormal_stress = -5\n", "consolidation.normal_stress"},
                      BadValue{"[consolidation]\nnormal_stress = 0\n", "consolidation.normal_stress"},
                      BadValue{"[shear]\nspeed = -1e-3\n", "shear.speed"},
                      BadValue{"[shear]\nfinal_strain = 0\n", "shear.final_strain"},
                      BadValue{"[shear]\nfinal_strain = 1.5\n", "shear.final_strain"},
                      BadValue{"[grains]\nd_max = 0.5e-3\n", "grains.d_max"},
                      BadValue{"[grains]\nfaces = 99\n", "grains.faces"},
                      BadValue{"[grains]\nshapes = 0\n", "grains.shapes"},
                      BadValue{"[grains]\npreset = \"cubes\"\n", "grains.preset"},
                      BadValue{"[specimen]\ne_max = 0.5\n", "specimen.e_max"},
                      BadValue{"[specimen]\nrelative_density = 1.2\n", "specimen.relative_density"},
                      BadValue{"[specimen]\nrelative_density = -0.1\n", "specimen.relative_density"},
                      BadValue{"[specimen]\nindices = \"mine\"\n", "specimen.indices"},
                      BadValue{"[specimen]\nown_e_max = 0.8\n", "specimen.own_e_max"},
                      BadValue{"[specimen]\nown_e_min = 0.6\nown_e_max = 0.5\n", "specimen.own_e_max"},
                      BadValue{"[specimen]\ndeposition_friction = -0.5\n", "specimen.deposition_friction"},
                      BadValue{"[box]\ngap = -1e-3\n", "box.gap"},
                      BadValue{"[box]\nlength = 0\n", "box.length"},
                      BadValue{"[box]\nwidth = -1\n", "box.width"},
                      BadValue{"[box]\nheight = 0.0\n", "box.height"},
                      BadValue{"[material]\nfriction = -0.1\n", "material.friction"},
                      BadValue{"[material]\npoisson_ratio = 0.5\n", "material.poisson_ratio"},
                      BadValue{"[material]\nrestitution = 0\n", "material.restitution"},
                      BadValue{"[material]\nrestitution = 1.01\n", "material.restitution"},
                      BadValue{"[material]\ndensity = nan\n", "material.density"},
                      BadValue{"[material]\nk_n = inf\n", "material.k_n"},
                      BadValue{"[numerics]\ntime_step = -1e-6\n", "numerics.time_step"},
                      BadValue{"[numerics]\nthreads = -2\n", "numerics.threads"},
                      BadValue{"[output]\nstrain_interval = 0\n", "output.strain_interval"},
                      BadValue{"[output]\nfolder = \"\"\n", "output.folder"}));

// A config written before the own index densities (issue 10) still parses.
// Since 2026-12-04 a target Dr is on the grains' own indices unless the
// config says indices = "lab" (the issue: "a target Dr means the material's
// own Dr unless the user sets void_ratio or says otherwise"): an old config's
// e_min/e_max are then the lab's, reported beside the own Dr, and its fixed
// deposition friction stays fixed. friction -1 (the default) searches.
TEST(Config, OldSpecimenKeysStillParse) {
  const LabSpec s = parse_config(
      "[specimen]\nrelative_density = 0.9\ne_max = 0.9\ne_min = 0.6\ntolerance = 0.03\n"
      "deposition_friction = 0.1\n", "old.toml");
  EXPECT_EQ(s.specimen.e_max, 0.9);
  EXPECT_EQ(s.specimen.e_min, 0.6);
  EXPECT_EQ(s.specimen.deposition_friction, 0.1);
  EXPECT_EQ(s.specimen.indices, "own");
  EXPECT_TRUE(s.targets_own_indices());
  EXPECT_FALSE(s.own_indices_known());  // grainlab run measures them
  const LabSpec lab = parse_config(
      "[specimen]\nindices = \"lab\"\nrelative_density = 0.9\ne_max = 0.9\ne_min = 0.6\n", "lab.toml");
  EXPECT_FALSE(lab.targets_own_indices());
  EXPECT_DOUBLE_EQ(lab.target_void_ratio(), 0.63);
  const LabSpec own = parse_config("[specimen]\nindices = \"own\"\nrelative_density = 0.5\n"
                                           "own_e_max = 0.8\nown_e_min = 0.6\ndeposition_friction = -1\n",
                                           "own.toml");
  EXPECT_TRUE(own.targets_own_indices());
  EXPECT_TRUE(own.own_indices_known());
  EXPECT_DOUBLE_EQ(own.target_void_ratio(), 0.7);
  EXPECT_EQ(own.specimen.deposition_friction, -1);  // chosen by bisection
  // Left out, the friction is the search's (since 2026-12-06: a fixed default
  // suits one grain class only; lab/deposition_friction.h).
  EXPECT_EQ(parse_config("[specimen]\nrelative_density = 0.5\n", "d.toml").specimen.deposition_friction, -1);
  // A void ratio overrides either index.
  EXPECT_FALSE(parse_config("[specimen]\nvoid_ratio = 0.6\n", "e.toml").targets_own_indices());
}

TEST(Config, UnknownSandPreset) {
  const std::string msg = parse_error("[material]\npreset = \"grifin\"\n");
  EXPECT_TRUE(has(msg, "test.toml (line 2)")) << msg;
  EXPECT_TRUE(has(msg, "Did you mean 'griffin'")) << msg;
  EXPECT_TRUE(has(msg, "crushed-limestone")) << msg;
}

TEST(Config, ValueNotInTheFileSaysSo) {
  // d_max stays at its default 0.841e-3 but d_min is raised above it: the
  // message names d_max and says the file does not set it.
  const std::string msg = parse_error("[grains]\nd_min = 1e-3\n");
  EXPECT_TRUE(has(msg, "grains.d_max")) << msg;
  EXPECT_TRUE(has(msg, "does not set it")) << msg;
}

TEST(Config, MissingMeshFolder) {
  const std::string msg = parse_error("[grains]\nfolder = \"/no/such/meshes\"\n");
  EXPECT_TRUE(has(msg, "grains.folder")) << msg;
  EXPECT_TRUE(has(msg, "/no/such/meshes")) << msg;
  EXPECT_TRUE(has(msg, "line 2")) << msg;
}

TEST(Config, ValidateOnItsOwn) {
  LabSpec s;
  EXPECT_NO_THROW(validate(s, "spec"));
  s.consolidation.normal_stress = -1;
  const std::string msg = error_of<InputError>([&] { validate(s, "my spec"); });
  EXPECT_TRUE(has(msg, "my spec: consolidation.normal_stress = -1 is impossible")) << msg;
}

TEST(Config, LoadConfigFromAFile) {
  test::IoTempDir dir;
  const auto file = dir.path / "run.toml";
  write_file_atomically(file, "seed = 42\n[shear]\nfinal_strain = 0.2\n");
  const LabSpec s = load_config(file);
  EXPECT_EQ(s.seed, 42u);
  EXPECT_EQ(s.settings<ShearSpec>().final_strain, 0.2);

  write_file_atomically(file, "[shear]\nspeed = -1\n");
  const std::string msg = error_of<InputError>([&] { load_config(file); });
  EXPECT_TRUE(has(msg, file.string() + " (line 2)")) << msg;

  const std::string missing = error_of<InputError>([&] { load_config(dir.path / "nope.toml"); });
  EXPECT_TRUE(has(missing, "nope.toml")) << missing;
  EXPECT_TRUE(has(missing, "does not exist")) << missing;
  const std::string folder = error_of<InputError>([&] { load_config(dir.path); });
  EXPECT_TRUE(has(folder, "is a folder")) << folder;
}

TEST(Config, SpecToJsonHasTheConfigKeys) {
  const LabSpec s = test::all_fields_changed();
  const nlohmann::json j = spec_to_json(s);
  EXPECT_EQ(j["seed"].get<std::uint64_t>(), s.seed);
  EXPECT_EQ(j["material"]["contact_law"].get<std::string>(), "hertz");
  EXPECT_EQ(j["material"]["friction"].get<double>(), s.material.grain.friction);
  EXPECT_EQ(j["grains"]["faces"].get<int>(), 321);
  EXPECT_EQ(j["output"]["folder"].get<std::string>(), s.output.folder);
  EXPECT_EQ(j["test"].get<std::string>(), "oedometer");
  EXPECT_EQ(j["oedometer"]["stresses"].get<std::vector<double>>(), s.settings<OedometerSpec>().stresses);
  EXPECT_EQ(j.size(), 12u);  // test, seed and ten tables

  test::IoTempDir dir;
  write_json_file(dir.path / "run.json", j);
  EXPECT_EQ(read_json_file(dir.path / "run.json"), j);
}

}  // namespace
}  // namespace grainlab
