// Every registered lab test runs with every synthetic grain class and no
// other setting but what makes it tiny, as a new user would write it:
//   test = "T"
//   [grains] preset = "P"
// plus a small box for the faceted grains (5.05 x 5.05 x 3.4 mm, 6 d_max
// across and 4 high, about 220-380 grains instead of about 1000; glass
// beads keep the default box, see tiny_keys) and a short end (1 % strain;
// one oedometer stage), loaded five times faster than the default
// (numerics.inertial_number 0.0045; it sets only the shear and axial speeds,
// after the specimen is prepared: at the default, the shear took about a
// third of an angular grains' direct shear run, 2026-12-06). (In a 5 d_max
// ring, glass beads' bulk, a few grains between the wall layers, came out at
// Dr 0.47-1.21 with no order in the friction, and 8 trials did not land.)
// Each goes through `grainlab run` to its end state, and its specimen is at
// the default target, Dr 0.9 on the grains' own index void ratios, within
// the default tolerance: the deposition friction is left to the
// preparation search (specimen.deposition_friction = -1, the default), which
// starts from the grain class's measured friction (lab/deposition_friction.h).
// Until it was (before 2026-12-06), the default was the rounded grains'
// fixed 0.032, and glass beads stopped after compaction at Dr 0.81-0.84
// in every test.
//
// Own index void ratios: the default rounded grains' are built in and glass
// beads' are measured by the run (5 s); sub-angular and angular grains'
// measurement takes 20 minutes to an hour, so the config gives them:
// sub-angular's as `grainlab run` measured them with the default keys (one
// seed), angular's as bench_preparation_range measured them for the
// crushed-limestone sand preset's grains (docs/direct_shear.md, "Reach,
// measured"; the index preparations do not use the material's friction).
// Each case is its own ctest (one thread), so they run side by side.
#include "command_line.h"
#include "io/json.h"
#include "lab/lab_spec.h"
#include "lab/lab_test.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <tuple>
#include <vector>

namespace {

namespace fs = std::filesystem;
using apps_test::run_grainlab;

// The grain classes of [grains] preset (io/config.cpp, "glass-beads | rounded | sub-angular | angular").
const std::vector<std::string> kPresets = {"glass-beads", "rounded", "sub-angular", "angular"};

// What makes a run tiny: its box and its end.
std::string tiny_keys(const std::string& test, const std::string& preset) {
  // Glass beads keep the default box: spheres are cheap, and in the small
  // box one friction's packings scattered wider than the tolerance (e
  // 0.562-0.636 between frictions 0.14 and 0.28 in one search, which then
  // gave up after 8 trials on another rounding of the same engine).
  std::string keys = preset == "glass-beads" ? "" : "[box]\nlength = 5.05e-3\nwidth = 5.05e-3\nheight = 3.4e-3\n";
  keys += "[numerics]\ninertial_number = 0.0045\n";
  if (test == "direct-shear") keys += "[shear]\nfinal_strain = 0.01\n";
  if (test == "triaxial") keys += "[triaxial]\nfinal_strain = 0.01\n";
  if (test == "oedometer") keys += "[oedometer]\nstresses = [200e3]\n";
  // The own indices of the 10 d_max index box, one seed (above).
  if (preset == "sub-angular") keys += "[specimen]\nown_e_min = 0.4020\nown_e_max = 0.6779\n";
  if (preset == "angular") keys += "[specimen]\nown_e_min = 0.468\nown_e_max = 0.758\n";
  return keys;
}

class PresetRun : public ::testing::TestWithParam<std::tuple<std::string, std::string>> {};

TEST_P(PresetRun, RunsToItsEndAtTheTargetDensity) {
  const auto& [test, preset] = GetParam();
  const fs::path dir = fs::path(GRAINLAB_BINARY).parent_path() / "test-work" / "presets" / (test + "_" + preset);
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "run.toml") << "test = \"" << test << "\"\n[grains]\npreset = \"" << preset << "\"\n"
                                  << tiny_keys(test, preset) << "[output]\nfolder = \"" << (dir / "out").string()
                                  << "\"\n";
  const auto r = run_grainlab(dir, "run run.toml --quiet --no-report --threads 1");
  ASSERT_EQ(r.exit_code, 0) << r.output;

  const nlohmann::json j = grainlab::read_json_file(dir / "out" / "run.json");
  EXPECT_EQ(j.at("phase"), "done") << r.output;
  const grainlab::LabSpec defaults;
  const double dr = j.at("preparation").at("relative_density").get<double>();
  EXPECT_NEAR(dr, defaults.specimen.relative_density, defaults.specimen.relative_density_tolerance) << r.output;
  // The friction the search chose is the one its landing trial used.
  const nlohmann::json& prep = j.at("specimen_preparation");
  ASSERT_FALSE(prep.at("trials").empty()) << r.output;
  EXPECT_EQ(prep.at("trials").back().at("deposition_friction"), prep.at("deposition_friction"));
  EXPECT_EQ(prep.at("deposition_friction"), j.at("preparation").at("deposition_friction"));
  std::printf("%s, %s: Dr %.3f at deposition friction %.4f after %zu trial(s)\n", test.c_str(), preset.c_str(), dr,
              prep.at("deposition_friction").get<double>(), prep.at("trials").size());
  fs::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(EveryTestAndPreset, PresetRun,
                         ::testing::Combine(::testing::ValuesIn(grainlab::lab_test_names()),
                                            ::testing::ValuesIn(kPresets)),
                         [](const auto& info) {
                           std::string name = std::get<0>(info.param) + "_" + std::get<1>(info.param);
                           for (char& c : name)
                             if (c == '-') c = '_';
                           return name;
                         });

}  // namespace
