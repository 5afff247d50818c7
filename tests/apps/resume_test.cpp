// `grainlab run` killed by SIGTERM during shear keeps a checkpoint and no torn
// file; `--resume` finishes the run, and its series.csv (analysis columns
// included) is the same, byte for byte, as that of a run that was never
// interrupted, and its ParaView collections list the same snapshots. A run
// whose report cannot be written (no Python with matplotlib) still succeeds.
#include "command_line.h"
#include "io/pvd_reader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace {

namespace fs = std::filesystem;

using apps_test::read_file;

// Starts `grainlab run CONFIG [--resume]` with its output in `log`.
pid_t start_run(const fs::path& config, bool resume, const fs::path& log) {
  std::vector<std::string> args = {GRAINLAB_BINARY, "run", config.string(), "--quiet"};
  if (resume) args.push_back("--resume");
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  pid_t pid = -1;
  const int rc = posix_spawn(&pid, GRAINLAB_BINARY, &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  return rc == 0 ? pid : -1;
}

int wait_exit(pid_t pid) {
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// A copy of checkpoint `from` at `to` whose grains' fingerprint (header
// bytes 12-15, outside the payload's checksum) says other grains.
void copy_with_other_grains(const fs::path& from, const fs::path& to) {
  std::string bytes = read_file(from);
  bytes[12] = static_cast<char>(bytes[12] ^ 0x5a);
  std::ofstream(to, std::ios::binary) << bytes;
}

std::size_t lines_in(const fs::path& p) {
  if (!fs::exists(p)) return 0;
  const std::string s = read_file(p);
  return static_cast<std::size_t>(std::count(s.begin(), s.end(), '\n'));
}

class Resume : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("grainlab-resume-test-" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // A box even smaller than the lab tests' (about 50 grains), sheared to 1 %;
  // whatever density it reaches is accepted. Seed 3: with seed 5 (used until
  // the GJK simplex cache changed the trajectories' rounding) the dense
  // packing this box makes (e 0.633) never met the consolidation's rest
  // test, a known limit of faceted packings (issue 10 item 1); measured 1 of
  // 7 seeds with and without the cache (docs/direct_shear.md).
  // `test_block`: "" for the direct shear, or a test's lines (which then use
  // glass beads: spheres, cheap).
  // `specimen_lines`: more lines of [specimen]; `material_lines` of [material] (direct shear only).
  fs::path config(const std::string& name, const std::string& test_block = "", const std::string& specimen_lines = "",
                  const std::string& material_lines = "", int seed = 3) {
    const fs::path p = dir_ / (name + ".toml");
    std::ofstream(p) << "seed = " << seed << "\n"
                     << (test_block.empty() ? std::string()
                                            : test_block + "\n[material]\npreset = \"glass-beads\"\n")
                     << (material_lines.empty() ? std::string() : "[material]\n" + material_lines + "\n")
                     << "[grains]\nshapes = 4\nfaces = 120\n"
                     << "[box]\nlength = 0.003\nwidth = 0.003\nheight = 0.002\n"
                     << "[specimen]\nindices = \"lab\"\ndeposition_friction = 0.05\ntolerance = 1.0\n"
                     << specimen_lines << "\n"
                     << "[shear]\nfinal_strain = 0.01\n[numerics]\nthreads = 1\n"
                     << "[output]\nsnapshot_interval = 0.004\nfolder = \"" << (dir_ / name).string() << "\"\n"
                     << output_lines_;
    return p;
  }
  // Runs the test of `test_block` straight through (folder "straight") and,
  // beside it, the same run killed by SIGTERM once its series.csv has
  // `lines` lines, then resumed (folder "killed"); no report (only the files
  // matter). Returns the straight run's series.csv.
  std::string straight_and_resumed(const std::string& test_block, std::size_t lines) {
    ::setenv("GRAINLAB_PYTHON", "/nonexistent/python3", 1);
    const pid_t straight = start_run(config("straight", test_block), false, dir_ / "straight.log");
    const fs::path killed = config("killed", test_block);
    const fs::path series = dir_ / "killed" / "series.csv";
    const pid_t pid = start_run(killed, false, dir_ / "killed.log");
    EXPECT_GT(straight, 0);
    EXPECT_GT(pid, 0);
    while (lines_in(series) < lines) {
      int status = 0;
      if (waitpid(pid, &status, WNOHANG) != 0) {
        ADD_FAILURE() << "the run ended early: " << read_file(dir_ / "killed.log");
        break;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    kill(pid, SIGTERM);
    EXPECT_EQ(wait_exit(pid), 130) << read_file(dir_ / "killed.log");
    EXPECT_EQ(wait_exit(straight), 0) << read_file(dir_ / "straight.log");
    EXPECT_LT(lines_in(series), lines_in(dir_ / "straight" / "series.csv")) << "killed after the end";
    EXPECT_EQ(wait_exit(start_run(killed, true, dir_ / "resumed.log")), 0) << read_file(dir_ / "resumed.log");
    ::unsetenv("GRAINLAB_PYTHON");
    EXPECT_NE(read_file(dir_ / "resumed.log").find("resuming at step"), std::string::npos);
    return read_file(dir_ / "straight" / "series.csv");
  }
  fs::path dir_;
  std::string output_lines_;  // more lines of [output]
};

}  // namespace

TEST_F(Resume, KilledDuringShearThenResumedGivesTheSameSeries) {
  // One run straight through, with no Python for its report (the run still
  // succeeds: its files are complete, and it says how to write the report
  // later) and, beside it, the same run stopped by SIGTERM once shear has
  // written a few rows.
  ::setenv("GRAINLAB_PYTHON", "/nonexistent/python3", 1);
  const pid_t straight = start_run(config("straight"), false, dir_ / "straight.log");
  ::unsetenv("GRAINLAB_PYTHON");
  const fs::path killed = config("killed");
  const fs::path series = dir_ / "killed" / "series.csv";
  const pid_t pid = start_run(killed, false, dir_ / "killed.log");
  ASSERT_GT(straight, 0);
  ASSERT_GT(pid, 0);
  while (lines_in(series) < 4) {
    int status = 0;
    ASSERT_EQ(waitpid(pid, &status, WNOHANG), 0) << "the run ended early: " << read_file(dir_ / "killed.log");
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  kill(pid, SIGTERM);
  ASSERT_EQ(wait_exit(pid), 130) << read_file(dir_ / "killed.log");
  ASSERT_EQ(wait_exit(straight), 0) << read_file(dir_ / "straight.log");
  EXPECT_NE(read_file(dir_ / "straight.log").find("warning: the HTML report was not written"), std::string::npos)
      << read_file(dir_ / "straight.log");
  const std::string expected = read_file(dir_ / "straight" / "series.csv");
  ASSERT_GT(lines_in(dir_ / "straight" / "series.csv"), 8u);
  ASSERT_NE(expected.find("rotation_mean_deg"), std::string::npos) << "the analysis columns are compared too";
  EXPECT_TRUE(fs::exists(dir_ / "killed" / "checkpoint.bin"));
  EXPECT_LT(lines_in(series), lines_in(dir_ / "straight" / "series.csv")) << "killed after the end";
  for (const auto& f : fs::directory_iterator(dir_ / "killed"))  // no torn temporary files
    EXPECT_EQ(f.path().string().find(".tmp"), std::string::npos) << f.path();

  ASSERT_EQ(wait_exit(start_run(killed, true, dir_ / "resumed.log")), 0) << read_file(dir_ / "resumed.log");
  EXPECT_NE(read_file(dir_ / "resumed.log").find("resuming at step"), std::string::npos);
  EXPECT_TRUE(fs::exists(dir_ / "killed" / "report" / "index.html")) << read_file(dir_ / "resumed.log");
  EXPECT_EQ(read_file(series), expected);
  // The resumed run kept the snapshots written before the kill and added the rest.
  for (const char* kind : {"grains", "contacts", "walls"}) {
    const std::string pvd = std::string("paraview/") + kind + ".pvd";
    const auto want = grainlab::read_pvd(dir_ / "straight" / pvd);
    EXPECT_GE(want.size(), 4u) << pvd;  // 0, 0.4 % and 0.8 % of strain, and the end
    EXPECT_EQ(grainlab::read_pvd(dir_ / "killed" / pvd), want) << pvd;
  }
}

// A run writes its prepared specimen (specimen.bin) as its loading begins;
// another run with specimen.from starts from it instead of preparing one.
// With the same config it shears exactly as the first did (series and first
// snapshot, byte for byte); with another friction it shears the same grains
// otherwise; with other grains (another seed) or a missing file it is refused
// before it writes anything.
// kill -9 saves nothing: the run is killed three times, once its first
// checkpoint is written (in the preparation) and twice in the shear, and
// each time `--resume` goes on from the last checkpoint written before the
// kill; the series at the end is the uninterrupted run's, byte for byte.
// Checkpoints every 0.05 s, so a kill falls between two of them.
// bench/kill9_resume.sh does the same at 20 moments of each lab test.
TEST_F(Resume, KilledByKill9ThreeTimesThenResumedGivesTheSameSeries) {
  ::setenv("GRAINLAB_PYTHON", "/nonexistent/python3", 1);
  output_lines_ = "checkpoint_interval = 0.05\n";
  const pid_t straight = start_run(config("straight"), false, dir_ / "straight.log");
  const fs::path killed = config("killed");
  const fs::path series = dir_ / "killed" / "series.csv";
  const fs::path checkpoint = dir_ / "killed" / "checkpoint.bin";
  pid_t pid = start_run(killed, false, dir_ / "killed.log");
  const std::function<bool()> kill_when[] = {[&] { return fs::exists(checkpoint); },
                                             [&] { return lines_in(series) >= 3; },
                                             [&] { return lines_in(series) >= 7; }};
  for (int k = 0; k < 3; ++k) {
    const fs::path log = dir_ / ("killed" + std::to_string(k) + ".log");
    while (!kill_when[k]()) {
      int status = 0;
      ASSERT_EQ(waitpid(pid, &status, WNOHANG), 0) << "the run ended before kill " << k << ": "
                                                   << read_file(dir_ / "killed.log");
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    kill(pid, SIGKILL);
    int status = 0;
    waitpid(pid, &status, 0);
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL) << "kill " << k;
    pid = start_run(killed, true, log);
    if (k < 2) continue;
    EXPECT_EQ(wait_exit(pid), 0) << read_file(log);
    EXPECT_NE(read_file(log).find("resuming at step"), std::string::npos) << read_file(log);
  }
  ASSERT_EQ(wait_exit(straight), 0) << read_file(dir_ / "straight.log");
  ::unsetenv("GRAINLAB_PYTHON");
  EXPECT_EQ(read_file(series), read_file(dir_ / "straight" / "series.csv"));
  for (const auto& f : fs::directory_iterator(dir_ / "killed"))  // the resumes removed the killed runs' temporaries
    EXPECT_EQ(f.path().filename().string().find(".tmp."), std::string::npos) << f.path();
}

TEST_F(Resume, ARunFromAnotherRunsSpecimenShearsThatSpecimen) {
  ::setenv("GRAINLAB_PYTHON", "/nonexistent/python3", 1);
  ASSERT_EQ(wait_exit(start_run(config("first"), false, dir_ / "first.log")), 0) << read_file(dir_ / "first.log");
  const fs::path specimen = dir_ / "first" / "specimen.bin";
  ASSERT_TRUE(fs::exists(specimen));
  const std::string from = "from = \"" + specimen.string() + "\"";
  ASSERT_EQ(wait_exit(start_run(config("same", "", from), false, dir_ / "same.log")), 0) << read_file(dir_ / "same.log");
  ::unsetenv("GRAINLAB_PYTHON");
  EXPECT_NE(read_file(dir_ / "same.log").find("starting from the specimen"), std::string::npos);
  EXPECT_EQ(read_file(dir_ / "first.log").find("starting from the specimen"), std::string::npos);
  const std::string expected = read_file(dir_ / "first" / "series.csv");
  ASSERT_GT(lines_in(dir_ / "first" / "series.csv"), 8u);
  EXPECT_EQ(read_file(dir_ / "same" / "series.csv"), expected);
  EXPECT_EQ(read_file(dir_ / "same" / "paraview" / "grains_0000.vtp"),
            read_file(dir_ / "first" / "paraview" / "grains_0000.vtp"));
  EXPECT_EQ(grainlab::read_pvd(dir_ / "same" / "paraview" / "grains.pvd"),
            grainlab::read_pvd(dir_ / "first" / "paraview" / "grains.pvd"));
  EXPECT_NE(read_file(dir_ / "same" / "run.json").find("\"specimen_from\""), std::string::npos);

  // Another friction: the same specimen (the first row, taken as loading
  // began, is the same), sheared otherwise.
  ASSERT_EQ(wait_exit(start_run(config("slippery", "", from, "friction = 0.05"), false, dir_ / "slippery.log")), 0)
      << read_file(dir_ / "slippery.log");
  const std::string slippery = read_file(dir_ / "slippery" / "series.csv");
  const auto first_rows = [](const std::string& csv) { return csv.substr(0, csv.find('\n', csv.find('\n') + 1)); };
  EXPECT_EQ(first_rows(slippery), first_rows(expected));
  EXPECT_NE(slippery, expected);

  // Other grains, or no file: refused, nothing written.
  EXPECT_NE(wait_exit(start_run(config("seed4", "", from, "", 4), false, dir_ / "seed4.log")), 0);
  EXPECT_NE(read_file(dir_ / "seed4.log").find("prepared with other grains, box, seed"), std::string::npos)
      << read_file(dir_ / "seed4.log");
  EXPECT_FALSE(fs::exists(dir_ / "seed4"));
  // The same config, but grains this grainlab would make otherwise (its
  // generator changed since the specimen, or the checkpoint, was written).
  copy_with_other_grains(specimen, dir_ / "other_grains.bin");
  const std::string other = "from = \"" + (dir_ / "other_grains.bin").string() + "\"";
  EXPECT_NE(wait_exit(start_run(config("other", "", other), false, dir_ / "other.log")), 0);
  EXPECT_NE(read_file(dir_ / "other.log").find("prepared with other grains than this grainlab makes"),
            std::string::npos)
      << read_file(dir_ / "other.log");
  EXPECT_FALSE(fs::exists(dir_ / "other"));
  const fs::path checkpoint = dir_ / "first" / "checkpoint.bin";
  copy_with_other_grains(checkpoint, checkpoint);
  const std::string before = read_file(dir_ / "first" / "series.csv");
  EXPECT_NE(wait_exit(start_run(config("first"), true, dir_ / "first_again.log")), 0);
  EXPECT_NE(read_file(dir_ / "first_again.log").find("written for other grains than this grainlab makes"),
            std::string::npos)
      << read_file(dir_ / "first_again.log");
  EXPECT_EQ(read_file(dir_ / "first" / "series.csv"), before);  // nothing lost
  const std::string missing = "from = \"" + (dir_ / "nowhere" / "specimen.bin").string() + "\"";
  EXPECT_NE(wait_exit(start_run(config("missing", "", missing), false, dir_ / "missing.log")), 0);
  EXPECT_NE(read_file(dir_ / "missing.log").find("no such file"), std::string::npos) << read_file(dir_ / "missing.log");
  EXPECT_FALSE(fs::exists(dir_ / "missing"));
}

TEST_F(Resume, OedometerKilledBetweenStagesThenResumedGivesTheSameSeries) {
  const std::string straight = straight_and_resumed(
      "test = \"oedometer\"\n[oedometer]\nstresses = [150e3, 200e3, 300e3]", 3);  // header, stages 0 and 1
  ASSERT_EQ(lines_in(dir_ / "straight" / "series.csv"), 5u) << straight;  // header and stages 0-3
  ASSERT_EQ(straight.rfind("time_s,stage,target_stress_Pa,vertical_stress_Pa", 0), 0u) << straight;
  EXPECT_EQ(read_file(dir_ / "killed" / "series.csv"), straight);
  const std::string run_json = read_file(dir_ / "killed" / "run.json");
  EXPECT_NE(run_json.find("\"compression_index\""), std::string::npos) << run_json;
  EXPECT_NE(run_json.find("\"test\": \"oedometer\""), std::string::npos) << run_json;
}

TEST_F(Resume, TriaxialKilledDuringShearThenResumedGivesTheSameSeries) {
  const std::string straight =
      straight_and_resumed("test = \"triaxial\"\n[triaxial]\nfinal_strain = 0.02", 5);  // header, 4 samples
  ASSERT_EQ(straight.rfind("time_s,axial_strain,volumetric_strain", 0), 0u) << straight;
  ASSERT_GT(lines_in(dir_ / "straight" / "series.csv"), 15u) << straight;  // a sample every 0.1 % to 2 %
  EXPECT_EQ(read_file(dir_ / "killed" / "series.csv"), straight);
  const std::string run_json = read_file(dir_ / "killed" / "run.json");
  EXPECT_NE(run_json.find("\"peak_friction_angle_deg\""), std::string::npos) << run_json;
}
