// `grainlab` used against its grain: no exception escapes (exit 2 for bad
// input, 3 for a fault of the system, each with a message, never 134), output
// lost to a full disk is an error, two runs cannot share an output folder, a
// file-size limit ends a run with a message and nothing half-written, and a
// hang-up stops a run with a checkpoint like SIGTERM does.
#include "command_line.h"
#include "core/folder_lock.h"
#include "geometry/mesh_io.h"
#include "geometry/primitives.h"
#include "io/config.h"

#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

namespace {

namespace fs = std::filesystem;

using apps_test::read_file;
using apps_test::Result;

// Runs `/bin/bash -c SCRIPT` (GRAINLAB in it names the binary), capturing stdout and stderr.
Result shell(const std::string& script) {
  return apps_test::run_shell("GRAINLAB=" + std::string(GRAINLAB_BINARY) + " /bin/bash -c '" + script + "'");
}

#define EXPECT_CONTAINS(text, part) EXPECT_NE((text).find(part), std::string::npos) << (text)

class HostileUse : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("grainlab-hostile-" + std::to_string(::getpid()) + "-" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // A config writing to `folder`; glass beads in a tiny box: the whole run takes about a second.
  fs::path config(const std::string& folder, bool beads = true) {
    const fs::path p = dir_ / "test.toml";
    std::ofstream(p) << "seed = 3\n[grains]\nshapes = 4\nfaces = 120\n"
                     << (beads ? "[material]\npreset = \"glass-beads\"\n" : "")
                     << "[box]\nlength = 0.003\nwidth = 0.003\nheight = 0.002\n"
                     << "[specimen]\nindices = \"lab\"\ndeposition_friction = 0.05\ntolerance = 1.0\n"
                     << "[shear]\nfinal_strain = 0.01\n[numerics]\nthreads = 1\n"
                     << "[output]\nsnapshot_interval = 0.004\nfolder = \"" << folder << "\"\n";
    return p;
  }
  // No exception escaped main (terminate prints its name and exits 134).
  static void expect_handled(const Result& r, int code) {
    EXPECT_EQ(r.exit_code, code) << r.output;
    EXPECT_EQ(r.output.find("terminate called"), std::string::npos) << r.output;
    EXPECT_CONTAINS(r.output, "grainlab: ");
  }

  fs::path dir_;
};

TEST_F(HostileUse, AConfigThatIsADeviceIsRefusedAtOnce) {
  const Result r = shell("$GRAINLAB run /dev/zero");
  expect_handled(r, 2);
  EXPECT_CONTAINS(r.output, "'/dev/zero' is a character device");
}

TEST_F(HostileUse, BadOutputFoldersAreInputErrorsNamingTheFolder) {
  std::ofstream(dir_ / "afile") << "x";
  Result r = shell("$GRAINLAB run " + config((dir_ / "afile").string()).string());
  expect_handled(r, 2);
  EXPECT_CONTAINS(r.output, (dir_ / "afile").string());
  r = shell("$GRAINLAB run " + config((dir_ / "afile" / "out").string()).string());  // a file as a parent
  expect_handled(r, 2);
  r = shell("$GRAINLAB run " + config((dir_ / std::string(300, 'f')).string()).string());
  expect_handled(r, 2);
  EXPECT_CONTAINS(r.output, "File name too long");
  EXPECT_CONTAINS(r.output, "(");  // the 300-character name quoted by its start
  EXPECT_LT(r.output.size(), 1000u);
  // Over the system's path limit (4096): refused by the config with the figure.
  std::string deep;
  for (int i = 0; i < 50; ++i) deep += "/" + std::string(100, 'd');
  r = shell("$GRAINLAB run " + config(dir_.string() + deep).string());
  expect_handled(r, 2);
  EXPECT_CONTAINS(r.output, "4096");
  // A parent that cannot hold folders (as root nothing is unwritable but /proc and /sys).
  r = shell("$GRAINLAB run " + config("/proc/grainlab-test/out").string());
  EXPECT_TRUE(r.exit_code == 2 || r.exit_code == 3) << r.output;
  EXPECT_CONTAINS(r.output, "/proc/grainlab-test/out");
  EXPECT_EQ(r.output.find("terminate called"), std::string::npos) << r.output;
}

TEST_F(HostileUse, OutputLostToAFullDiskIsAnError) {
  Result r = shell("$GRAINLAB run --print-defaults > /dev/full");
  expect_handled(r, 3);
  EXPECT_CONTAINS(r.output, "No space left on device");
  grainlab::write_stl(grainlab::icosphere(1e-3, 2), dir_ / "grain.stl");
  r = shell("$GRAINLAB grains stats " + (dir_ / "grain.stl").string() + " > /dev/full");
  expect_handled(r, 3);
  EXPECT_CONTAINS(r.output, "standard output");
  // A file argument that is a device is refused before minutes of measuring
  // (as root the rename replaced /dev/full with a file, and it said "wrote /dev/full").
  r = shell("$GRAINLAB grains index --json /dev/full");
  expect_handled(r, 2);
  EXPECT_CONTAINS(r.output, "'/dev/full': it is a character device");
  EXPECT_TRUE(fs::is_character_file("/dev/full"));
}

TEST_F(HostileUse, TwoRunsCannotShareAnOutputFolder) {
  const fs::path out = dir_ / "out";
  const grainlab::FolderLock held(out, "grainlab run");  // as a run under way holds it
  const Result r = shell("$GRAINLAB run --no-report " + config(out.string()).string());
  expect_handled(r, 2);
  EXPECT_CONTAINS(r.output, out.string());
  EXPECT_CONTAINS(r.output, "process " + std::to_string(::getpid()));
  EXPECT_FALSE(fs::exists(out / "config.toml")) << "the refused run wrote into the folder";
}

TEST_F(HostileUse, AFileSizeLimitEndsARunWithAMessageAndNothingHalfWritten) {
  // 20 KiB: the config and the first rows fit, a ParaView snapshot or checkpoint does not.
  const fs::path out = dir_ / "out";
  const Result r = shell("ulimit -f 20; exec $GRAINLAB run --no-report --quiet " + config(out.string()).string());
  expect_handled(r, 3);
  EXPECT_CONTAINS(r.output, "File too large");
  EXPECT_CONTAINS(r.output, "ulimit -f");
  EXPECT_CONTAINS(r.output, "every file written before is whole");
  // What is there under a final name is whole: the config parses, the series ends its last row.
  for (const auto& e : fs::recursive_directory_iterator(out))
    EXPECT_EQ(e.path().filename().string().find(".tmp."), std::string::npos) << e.path();
  EXPECT_NO_THROW(grainlab::load_config(out / "config.toml"));
  if (fs::exists(out / "series.csv")) {
    EXPECT_EQ(read_file(out / "series.csv").back(), '\n');
  }
  EXPECT_FALSE(fs::exists(out / "run.json"));
}

TEST_F(HostileUse, AHangUpStopsARunWithACheckpointAndResumeClearsStaleTemporaries) {
  const fs::path out = dir_ / "out";
  const fs::path cfg = config(out.string(), false);  // faceted grains: a few seconds
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    const int log = ::open((dir_ / "run.log").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(log, 1);
    ::dup2(log, 2);
    ::execl(GRAINLAB_BINARY, GRAINLAB_BINARY, "run", cfg.c_str(), "--quiet", "--no-report", nullptr);
    ::_exit(127);
  }
  // Wait until the run steps (it writes config.toml just before; stdout, a file, is not flushed).
  for (int i = 0; i < 6000 && !fs::exists(out / "config.toml"); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  ::kill(pid, SIGHUP);
  int status = 0;
  ::waitpid(pid, &status, 0);
  const std::string log = read_file(dir_ / "run.log");
  ASSERT_TRUE(WIFEXITED(status)) << "killed by the hang-up: " << log;
  EXPECT_EQ(WEXITSTATUS(status), 130) << log;
  EXPECT_CONTAINS(log, "stopped by signal 1");
  EXPECT_TRUE(fs::exists(out / "checkpoint.bin")) << log;
  // A temporary a kill -9 would leave, then --resume: removed, and the run ends.
  std::ofstream(out / ".series.csv.tmp.99999.0") << "torn";
  const Result r = shell("$GRAINLAB run --quiet --no-report --resume " + cfg.string());
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_CONTAINS(r.output, "removed 1 temporary file");
  EXPECT_FALSE(fs::exists(out / ".series.csv.tmp.99999.0"));
  EXPECT_TRUE(fs::exists(out / "run.json"));
}

}  // namespace
