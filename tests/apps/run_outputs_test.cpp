// What `grainlab run` leaves in its run folder, from ONE tiny run through the
// command line (shared by the tests below, even across processes; it takes
// most of their time), run from a folder away from the source tree: series.csv with the analysis
// columns, analysis/*.csv and *.json, paraview/ snapshots that read back,
// run.json's micromechanics entries, and report/index.html with every figure
// the report promised. Also `grainlab report` on its own.
#include "command_line.h"
#include "io/json.h"
#include "io/pvd_reader.h"
#include "io/table.h"
#include "io/vtp_reader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/wait.h>
#include <unistd.h>

namespace {

namespace fs = std::filesystem;
using grainlab::PolyData;
using grainlab::PvdEntry;
using grainlab::Table;

using apps_test::read_file;
using apps_test::Result;
using apps_test::run_grainlab;

const std::vector<std::string> kAnalysisColumns = {"rotation_mean_deg", "rotation_band_deg",
                                                   "coordination_number_band", "fabric_psi",
                                                   "fabric_psi_band", "band_low_m", "band_high_m"};
constexpr double kHeight = 2.5e-3;  // m, box.height of the run below

// The tiny box of the lab tests (tests/lab/tiny_box.h, about 85 grains),
// sheared to 2 %, a snapshot every 1 %; whatever density it reaches is accepted.
const char* const kConfig =
    "seed = 5\n[grains]\nshapes = 4\nfaces = 120\n"
    "[box]\nlength = 0.0035\nwidth = 0.0035\nheight = 0.0025\n"
    "[specimen]\nindices = \"lab\"\ndeposition_friction = 0.05\ntolerance = 1.0\n"
    "[shear]\nfinal_strain = 0.02\n"
    "[numerics]\nthreads = 1\n"
    "[output]\nsnapshot_interval = 0.01\nfolder = ";

// The run, done once for all the tests below. ctest runs each TEST in its own
// process, so the run folder is kept in the build tree (test-work/run-outputs)
// with a stamp of the binary and the config: the first process to take the
// lock runs it, the others (in parallel or later) wait for it and reuse it; a
// rebuilt binary runs it again.
struct TinyCliRun {
  fs::path dir, out;
  Result result;

  TinyCliRun() {
    const fs::path binary = GRAINLAB_BINARY;
    dir = binary.parent_path() / "test-work" / "run-outputs";
    out = dir / "run";
    fs::create_directories(dir.parent_path());
    const std::string config = std::string(kConfig) + "\"" + out.string() + "\"\n";
    const std::string stamp = config + std::to_string(fs::file_size(binary)) + " " +
                              std::to_string(fs::last_write_time(binary).time_since_epoch().count()) + "\n";
    const int lock = ::open((dir.string() + ".lock").c_str(), O_CREAT | O_RDWR, 0644);
    ::flock(lock, LOCK_EX);
    const std::string done = read_file(dir / "done");
    if (done.rfind(stamp, 0) == 0) {
      result = {std::stoi(done.substr(stamp.size())), read_file(dir / "output.txt")};
    } else {
      fs::remove_all(dir);
      fs::create_directories(dir / "elsewhere");
      std::ofstream(dir / "tiny.toml") << config;
      result = run_grainlab(dir / "elsewhere", "run '" + (dir / "tiny.toml").string() + "' --quiet");
      std::ofstream(dir / "output.txt") << result.output;
      std::ofstream(dir / "done") << stamp << result.exit_code << "\n";
    }
    ::flock(lock, LOCK_UN);
    ::close(lock);
  }
};

const TinyCliRun& tiny_run() {
  static const TinyCliRun run;
  return run;
}

#define REQUIRE_RUN(r)                                                          \
  const TinyCliRun& r = tiny_run();                                             \
  ASSERT_EQ(r.result.exit_code, 0) << r.result.output;

}  // namespace

TEST(RunOutputs, SeriesHasTheAnalysisColumnsFiniteOnceSheared) {
  REQUIRE_RUN(r);
  const Table t = grainlab::read_csv(r.out / "series.csv");
  ASSERT_GE(t.rows.size(), 15u);
  for (const std::string& c : kAnalysisColumns) ASSERT_NO_THROW(t.column(c)) << c;
  const std::size_t rot = t.column("rotation_mean_deg"), psi = t.column("fabric_psi"),
                    low = t.column("band_low_m"), high = t.column("band_high_m"), strain = t.column("shear_strain");
  // Strain 0: nothing has turned and no band exists yet.
  EXPECT_EQ(t.rows[0][strain], 0.0);
  EXPECT_LT(t.rows[0][rot], 1e-9);  // deg; q q^-1 of a stored quaternion is the identity up to rounding
  EXPECT_TRUE(std::isnan(t.rows[0][low]));
  EXPECT_TRUE(std::isfinite(t.rows[0][psi]));
  // After the first few samples every column is finite, and the band is inside the specimen.
  for (std::size_t k = 3; k < t.rows.size(); ++k) {
    for (const std::string& c : kAnalysisColumns)
      EXPECT_TRUE(std::isfinite(t.rows[k][t.column(c)])) << c << " at row " << k;
    EXPECT_GT(t.rows[k][rot], 0.0);
    EXPECT_GE(t.rows[k][psi], 0.0);
    EXPECT_LE(t.rows[k][psi], 1.0);
    EXPECT_GE(t.rows[k][low], 0.0);
    EXPECT_LT(t.rows[k][low], t.rows[k][high]);
    EXPECT_LE(t.rows[k][high], 1.2 * kHeight);
  }
}

TEST(RunOutputs, AnalysisFilesFollowTheReportContract) {
  REQUIRE_RUN(r);
  const fs::path a = r.out / "analysis";
  const Table profile = grainlab::read_csv(a / "profile.csv");
  EXPECT_EQ(profile.columns, (std::vector<std::string>{"z_m", "displacement_x_m", "count"}));
  ASSERT_GE(profile.rows.size(), 2u);
  double grains = 0;
  for (const auto& row : profile.rows) grains += row[2];
  const nlohmann::json run = grainlab::read_json_file(r.out / "run.json");
  EXPECT_EQ(grains, run["grains"].get<double>()) << "every grain is in one layer";
  // The top layer moved with the upper half, the bottom one stayed.
  EXPECT_GT(profile.rows.back()[1], profile.rows.front()[1]);

  const nlohmann::json band = grainlab::read_json_file(a / "band.json");
  ASSERT_TRUE(band["found"].get<bool>()) << band.dump();
  EXPECT_LT(band["low_m"].get<double>(), band["high_m"].get<double>());
  EXPECT_TRUE(band["method"].is_string());

  const nlohmann::json fabric = grainlab::read_json_file(a / "fabric.json");
  for (const char* set : {"all", "band"}) {
    const nlohmann::json& f = fabric[set];
    ASSERT_TRUE(f.contains("normals")) << set << ": " << f.dump().substr(0, 300);
    EXPECT_EQ(f["normals"].size(), f["contacts"].get<std::size_t>()) << set;
    EXPECT_FALSE(f["normals_subsampled"].get<bool>());
    EXPECT_EQ(f["phi"].size(), 3u);
    EXPECT_EQ(f["D2"].size(), 3u);
    EXPECT_EQ(f["D4"][2][2][2].size(), 3u);
    EXPECT_EQ(f["principal_values"].size(), 3u);
    const double psi = f["psi"].get<double>();
    EXPECT_TRUE(psi >= 0 && psi <= 1) << psi;
    double trace = 0;
    for (int i = 0; i < 3; ++i) trace += f["phi"][i][i].get<double>();
    EXPECT_NEAR(trace, 1.0, 1e-12) << set;
  }

  const Table chains = grainlab::read_csv(a / "force_chains.csv");
  EXPECT_EQ(chains.columns, (std::vector<std::string>{"x1_m", "y1_m", "z1_m", "x2_m", "y2_m", "z2_m", "force_N",
                                                      "tangential_force_N", "strong"}));
  EXPECT_EQ(chains.rows.size(), fabric["all"]["contacts"].get<std::size_t>());
  for (const auto& row : chains.rows) EXPECT_GE(row[6], 0.0);

  // The engine's derived series: one dilation angle per series row.
  const Table derived = grainlab::read_csv(a / "derived.csv");
  EXPECT_EQ(derived.columns, (std::vector<std::string>{"shear_strain", "dilation_angle_deg"}));
  EXPECT_EQ(derived.rows.size(), grainlab::read_csv(r.out / "series.csv").rows.size());
  // The rose histogram and Kanatani grid the report plots.
  EXPECT_EQ(fabric["all"]["kanatani_grid"]["density_per_sr"].size(), 31u);
  EXPECT_GE(fabric["all"]["rose"]["density_per_sr"].size(), 5u);
}

TEST(RunOutputs, RunJsonHasRoundnessPeakPsiAndLoveWeberStress) {
  REQUIRE_RUN(r);
  const nlohmann::json run = grainlab::read_json_file(r.out / "run.json");
  const double roundness = run["mean_roundness"].get<double>();
  EXPECT_GT(roundness, 0.2);  // sub-angular grains: about 0.45
  EXPECT_LE(roundness, 1.0);
  const Table t = grainlab::read_csv(r.out / "series.csv");
  double peak = 0;
  for (const auto& row : t.rows) peak = std::max(peak, row[t.column("fabric_psi")]);
  EXPECT_EQ(run["peaks"]["fabric_psi"].get<double>(), peak);
  // Love-Weber sigma_zz against the cap's stress: the same load, seen from the contacts.
  const nlohmann::json& f = run["final"];
  ASSERT_EQ(f["love_weber_stress_Pa"].size(), 3u);
  const double zz = f["love_weber_stress_Pa"][2][2].get<double>(), cap = f["cap_normal_stress_Pa"].get<double>();
  EXPECT_NEAR(zz / cap, 1.0, 0.25) << "sigma_zz " << zz << " Pa, cap " << cap << " Pa";
  EXPECT_GT(f["love_weber_stress_Pa"][0][0].get<double>(), 0.0);
  EXPECT_GT(f["specimen_volume_m3"].get<double>(), 0.0);
}

TEST(RunOutputs, ParaViewCollectionsListEverySnapshotAndTheFilesReadBack) {
  REQUIRE_RUN(r);
  const fs::path pv = r.out / "paraview";
  std::vector<double> times;
  for (const char* kind : {"grains", "contacts", "walls"}) {
    const std::vector<PvdEntry> entries = grainlab::read_pvd(pv / (std::string(kind) + ".pvd"));
    // The start of shear, 1 % and 2 % (the last sample is the end, or a final snapshot follows it).
    ASSERT_GE(entries.size(), 3u) << kind;
    ASSERT_LE(entries.size(), 4u) << kind;
    std::set<std::string> listed;
    for (std::size_t k = 0; k < entries.size(); ++k) {
      listed.insert(entries[k].file);
      if (k > 0) {
        EXPECT_GT(entries[k].time, entries[k - 1].time) << kind;
      }
      EXPECT_NO_THROW(grainlab::read_vtp(pv / entries[k].file)) << entries[k].file;
    }
    std::set<std::string> on_disk;  // every file of this kind is listed
    for (const auto& e : fs::directory_iterator(pv))
      if (e.path().filename().string().rfind(std::string(kind) + "_", 0) == 0) on_disk.insert(e.path().filename().string());
    EXPECT_EQ(on_disk, listed) << kind;
    if (times.empty()) {
      for (const PvdEntry& e : entries) times.push_back(e.time);
    } else {
      ASSERT_EQ(entries.size(), times.size());
      for (std::size_t k = 0; k < times.size(); ++k) EXPECT_EQ(entries[k].time, times[k]) << kind;
    }
  }
  // The first snapshot is the start of shear: no displacement yet. The last has moved grains.
  const std::vector<PvdEntry> grains = grainlab::read_pvd(pv / "grains.pvd");
  for (int which : {0, 1}) {
    const PolyData pd = grainlab::read_vtp(pv / (which == 0 ? grains.front().file : grains.back().file));
    EXPECT_STREQ(pd.points.type_name(), "Float32");
    std::set<std::string> names;
    const grainlab::VtkArray* displacement = nullptr;
    for (const auto& a : pd.point_data) {
      names.insert(a.name);
      if (a.name == "displacement") displacement = &a;
    }
    for (const char* n : {"grain_id", "displacement", "rotation", "velocity", "coordination", "in_shear_band"})
      EXPECT_TRUE(names.count(n)) << n;
    ASSERT_NE(displacement, nullptr);
    double largest = 0;
    std::visit([&](const auto& v) { for (auto x : v) largest = std::max(largest, std::abs(double(x))); },
               displacement->values);
    if (which == 0) {
      EXPECT_EQ(largest, 0.0);
    } else {
      EXPECT_GT(largest, 1e-5);  // m: 2 % of 3.5 mm is 70 um
    }
  }
}

TEST(RunOutputs, ReportNamesEveryFigureItPromised) {
  REQUIRE_RUN(r);
  const fs::path report = r.out / "report" / "index.html";
  ASSERT_TRUE(fs::exists(report)) << r.result.output;
  EXPECT_NE(r.result.output.find("report: " + fs::canonical(report).string()), std::string::npos)
      << "the report path is printed: " << r.result.output;
  // The figures the report said it wrote ...
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.result.output, m, std::regex(R"re(figures written \((\d+)\): ([^\n]*))re")))
      << r.result.output;
  std::set<std::string> promised;
  std::istringstream list(m[2].str());
  for (std::string name; std::getline(list, name, ',');) promised.insert(name.substr(name.find_first_not_of(' ')));
  EXPECT_EQ(promised.size(), std::stoul(m[1].str()));
  // ... all eight of a complete run ...
  EXPECT_EQ(promised.size(), 8u) << m[0];
  // ... are shown by the page, and every image it shows exists.
  const std::string html = read_file(report);
  std::set<std::string> shown;
  const std::regex img(R"re(<img src="([^"]+)")re");
  for (auto it = std::sregex_iterator(html.begin(), html.end(), img); it != std::sregex_iterator(); ++it)
    shown.insert((*it)[1].str());
  EXPECT_EQ(shown, promised);
  for (const std::string& png : shown) EXPECT_TRUE(fs::exists(report.parent_path() / png)) << png;
}

TEST(RunOutputs, ReportCommandWorksFromAnyFolderWithOut) {
  REQUIRE_RUN(r);
  const fs::path out = r.dir / "elsewhere" / "again";
  fs::remove_all(out);
  const Result rep = run_grainlab("/", "report '" + r.out.string() + "' --out '" + out.string() + "'");
  ASSERT_EQ(rep.exit_code, 0) << rep.output;
  EXPECT_TRUE(fs::exists(out / "index.html"));
  EXPECT_NE(rep.output.find("index.html"), std::string::npos) << rep.output;
}

// A largest F/N in the last 5 % of the test's strain is not called a peak:
// run.json says whether the tiny run's is one (analysis/peak.h's rule on its
// peak strain), its report says "no peak" exactly when run.json does, and a
// copy whose run.json puts the peak at the final strain, judged no peak,
// says so.
TEST(RunOutputs, ReportCallsNoPeakALargestValueAtTheEnd) {
  REQUIRE_RUN(r);
  const std::string no_peak = "no peak: F/N is largest at the end of the test";
  const nlohmann::json run = grainlab::read_json_file(r.out / "run.json");
  const double final_strain = 0.02, at = run["peaks"]["strain_at_peak_friction"].get<double>();
  ASSERT_TRUE(run["peaks"].contains("friction_is_peak")) << run["peaks"].dump();
  ASSERT_TRUE(run["peaks"].contains("dilation_is_peak")) << run["peaks"].dump();
  const bool at_end = !run["peaks"]["friction_is_peak"].get<bool>();
  EXPECT_EQ(at_end, at >= 0.95 * final_strain - 1e-9) << "peak strain " << at;
  EXPECT_EQ(read_file(r.out / "report" / "index.html").find(no_peak) != std::string::npos, at_end)
      << "peak strain " << at;

  const fs::path copy = r.dir / "no-peak";
  fs::remove_all(copy);
  fs::copy(r.out, copy, fs::copy_options::recursive);
  nlohmann::json edited = run;
  edited["peaks"]["strain_at_peak_friction"] = final_strain;
  edited["peaks"]["friction_is_peak"] = false;
  std::ofstream(copy / "run.json") << edited.dump(1);
  const Result rep = run_grainlab("/", "report '" + copy.string() + "'");
  ASSERT_EQ(rep.exit_code, 0) << rep.output;
  const std::string html = read_file(copy / "report" / "index.html");
  EXPECT_NE(html.find(no_peak), std::string::npos);
  EXPECT_NE(html.find("(the end of the test: no peak reached)"), std::string::npos);

  // The comparison of the two: both figures, and its table marks each run without a peak.
  const fs::path cmp = r.dir / "comparison";
  fs::remove_all(cmp);
  const Result both =
      run_grainlab("/", "report '" + r.out.string() + "' '" + copy.string() + "' --out '" + cmp.string() + "'");
  ASSERT_EQ(both.exit_code, 0) << both.output;
  EXPECT_NE(both.output.find("figures written (2): stress_strain_overlay.png, peaks_vs_roundness.png"),
            std::string::npos)
      << both.output;
  const std::string table = read_file(cmp / "index.html");
  std::size_t marks = 0;
  for (std::size_t at_ = table.find("(the end: no peak)"); at_ != std::string::npos;
       at_ = table.find("(the end: no peak)", at_ + 1))
    ++marks;
  EXPECT_EQ(marks, at_end ? 2u : 1u);
}

TEST(ReportCommand, EmbedsThePackageOfTheSourceTree) {
  const fs::path source = fs::path(GRAINLAB_TEST_DATA).parent_path().parent_path() / "python" / "grainlab" / "report";
  const fs::path dir = fs::temp_directory_path() / ("grainlab-embed-test-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const Result r = run_grainlab(dir, "report --write-package pkg");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  // Every .py file of the source, with the same text, and no other.
  std::size_t sources = 0;
  for (const auto& e : fs::directory_iterator(source)) {
    if (e.path().extension() != ".py") continue;
    ++sources;
    EXPECT_TRUE(read_file(dir / "pkg" / "grainlab" / "report" / e.path().filename()) == read_file(e.path()))
        << "rebuild: the binary embeds an old " << e.path().filename();
  }
  std::size_t written = 0;
  for (const auto& e : fs::directory_iterator(dir / "pkg" / "grainlab" / "report")) written += e.is_regular_file();
  EXPECT_GT(sources, 10u);
  EXPECT_EQ(written, sources) << "rebuild: the binary embeds a file the source no longer has, or lacks one";
  EXPECT_TRUE(fs::is_regular_file(dir / "pkg" / "grainlab" / "__init__.py"));
  fs::remove_all(dir);
}

TEST(ReportCommand, SaysWhatToInstallWithoutMatplotlib) {
  const Result r = run_grainlab("/", "report /nonexistent-run", "GRAINLAB_PYTHON=/nonexistent/python3");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("matplotlib"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("python3-matplotlib"), std::string::npos) << r.output;
}

TEST(ReportCommand, RefusesAFolderThatIsNotARun) {
  const Result r = run_grainlab("/", "report /nonexistent-run");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("not a folder"), std::string::npos) << r.output;
}
