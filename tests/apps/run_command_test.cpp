// `grainlab run` refuses bad configs with a clear message, a non-zero exit,
// and writes nothing.
#include "command_line.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

namespace {

namespace fs = std::filesystem;

using apps_test::Result;

// Runs the grainlab binary with `args`, capturing stdout and stderr.
Result cli(const std::string& args) { return apps_test::run_shell(std::string(GRAINLAB_BINARY) + " " + args); }

class RunCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("grainlab-run-test-" + std::to_string(::getpid()) + "-" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // A config that sends its output into the test folder, plus `extra` lines.
  fs::path config(const std::string& extra) {
    const fs::path p = dir_ / "test.toml";
    std::ofstream(p) << "[output]\nfolder = \"" << (dir_ / "out").string() << "\"\n" << extra;
    return p;
  }
  bool wrote_nothing() const { return !fs::exists(dir_ / "out"); }

  fs::path dir_;
};

TEST_F(RunCommand, PrintDefaultsPrintsEveryTable) {
  const Result r = cli("run --print-defaults");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  // Every table, with units in the comments (io's tests check that it parses
  // back to the defaults field by field).
  for (const char* key : {"[grains]", "[material]", "[box]", "[specimen]", "[consolidation]", "[shear]",
                          "[numerics]", "[output]", "normal_stress", "Pa", "seed"})
    EXPECT_NE(r.output.find(key), std::string::npos) << key;
}

TEST_F(RunCommand, UnknownKeyIsNamedWithItsFile) {
  const Result r = cli("run " + config("[consolidation]\nnormal_stres = 100e3\n").string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("normal_stres"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("normal_stress"), std::string::npos) << "should suggest the right key: " << r.output;
  EXPECT_NE(r.output.find("test.toml"), std::string::npos) << r.output;
  EXPECT_TRUE(wrote_nothing());
}

TEST_F(RunCommand, NegativeStressIsRefused) {
  const Result r = cli("run " + config("[consolidation]\nnormal_stress = -5\n").string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("consolidation.normal_stress"), std::string::npos) << r.output;
  EXPECT_TRUE(wrote_nothing());
}

TEST_F(RunCommand, StepAboveTheStableLimitIsRefused) {
  const Result r = cli("run " + config("[grains]\nshapes = 2\nfaces = 200\n[numerics]\ntime_step = 1e-3\n").string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("critical"), std::string::npos) << r.output;
  EXPECT_TRUE(wrote_nothing());
}

TEST_F(RunCommand, MissingMeshFolderIsRefused) {
  const Result r = cli("run " + config("[grains]\nfolder = \"/no/such/scan/folder\"\n").string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("/no/such/scan/folder"), std::string::npos) << r.output;
  EXPECT_TRUE(wrote_nothing());
}

TEST_F(RunCommand, MissingConfigFileIsRefused) {
  const Result r = cli("run " + (dir_ / "nope.toml").string());
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("nope.toml"), std::string::npos) << r.output;
}

}  // namespace

namespace {

// From a 3D image to a consolidated specimen in two commands (issue 12):
// `ct segment` a synthetic scan, then `run` with grains.scan.
TEST_F(RunCommand, AScanIsSegmentedThenRunFromWhereItsGrainsWere) {
  const fs::path scan = dir_ / "scan.nrrd", grains = dir_ / "grains";
  ASSERT_EQ(cli("ct synth --out " + scan.string()).exit_code, 0);
  const Result seg = cli("ct segment " + scan.string() + " --out " + grains.string() + " --quiet");
  ASSERT_EQ(seg.exit_code, 0) << seg.output;
  const Result r = cli(config("[grains]\nscan = \"" + grains.string() +
                                   "\"\nscan_border = \"keep\"\n[box]\nlength = 0.0045\nwidth = 0.0045\n"
                                   "height = 0.003\n[shear]\nfinal_strain = 0.002\n").string().insert(0, "run --no-report --quiet "));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::ifstream json(dir_ / "out" / "run.json");
  const std::string text((std::istreambuf_iterator<char>(json)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("\"scan\""), std::string::npos);
  EXPECT_NE(text.find("\"position_spread\""), std::string::npos);
  EXPECT_NE(text.find("\"grains\": 8"), std::string::npos) << text.substr(0, 400);  // every grain of the scan
}

TEST_F(RunCommand, AScanFolderWithoutGrainsCsvIsRefused) {
  fs::create_directories(dir_ / "empty");
  const Result r = cli("run " + config("[grains]\nscan = \"" + (dir_ / "empty").string() + "\"\n").string());
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("no grains.csv there"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("grainlab ct segment"), std::string::npos) << r.output;
  EXPECT_TRUE(wrote_nothing());
}

}  // namespace

// `grainlab grains index --keep FOLDER` (the mechanism of going on from a
// kept preparation is tests/io/kept_preparations_test.cpp): a finished
// measurement is printed again without measuring, and a folder that holds
// another box is refused with exit 2.
TEST_F(RunCommand, IndexKeepPrintsAFinishedMeasurementAndRefusesAnotherBox) {
  const std::string index = "grains index --preset glass-beads --shapes 4 --seeds 1 --height-diameters 6 --keep " +
                            (dir_ / "keep").string() + " --box-diameters ";
  const Result first = cli(index + "6");
  ASSERT_EQ(first.exit_code, 0) << first.output;
  EXPECT_TRUE(fs::exists(dir_ / "keep" / "index_densities.json"));
  EXPECT_FALSE(fs::exists(dir_ / "keep" / "index_e_min_seed1.bin"));  // done: in the record
  const auto own_e_min = [](const std::string& out) { return out.substr(out.find("own_e_min"), 20); };
  const Result again = cli(index + "6");
  ASSERT_EQ(again.exit_code, 0) << again.output;
  EXPECT_NE(again.output.find("already holds this measurement"), std::string::npos) << again.output;
  EXPECT_EQ(own_e_min(again.output), own_e_min(first.output));
  const Result other = cli(index + "7");
  EXPECT_EQ(other.exit_code, 2) << other.output;
  EXPECT_NE(other.output.find("another box or loose friction"), std::string::npos) << other.output;
}
