// The four-sand study of the paper (He, Zheng & Schaefer 2021, section 5 and
// Appendices 2-3): glass beads, rounded, sub-angular and angular grains, each
// prepared dense on its own index void ratios and sheared under 100 kPa; then
// glass beads under the three damping sets of Appendix 2. Not a test: it
// writes run folders and one comparison report (python -m grainlab.report.study).
//
//   build/study_four_sands [--quick] [--out DIR] [--grainlab PATH] [--threads N]
//                          [--only sands|damping|SAND,SAND...] [--seeds N] [--estimate]
//
// Per sand (Table 1 material through lab/sand_presets.h), one `grainlab run`
// on the config written to DIR/configs/<sand>.toml, which does the whole
// preparation as any run asking for a Dr on its own indices does:
//   1. the own index void ratios (lab/index_densities.h: e_min frictionless
//      deposition and compaction, e_max deposition at friction 1.0, in a box
//      10 d_max square, bulk void ratios), kept in the run folder;
//   2. the deposition friction that gives Dr 0.9 +- 0.05 on them, by the
//      bisection of lab/preparation_search.h; the trial that lands is the
//      specimen;
//   3. the shear to 10 % strain (angular grains to 20 %, Appendix 3) at
//      I = 9e-4 (<= 1e-3, quasi-static).
// DIR/study.json copies from each run.json what the report tabulates
// (e_min, e_max, the friction, the void ratio, the trials) and the wall times.
// Damping set: glass beads, contact_law hertz-user (the paper's k_n, k_t,
// gamma_n, gamma_t). One specimen, prepared with the paper's (gamma_n,
// gamma_t) = (40, 20) and the glass beads' own indices and deposition
// friction from their run, is sheared under (40, 20), then under (20, 10)
// and (80, 40) from the same prepared specimen (specimen.from = its
// specimen.bin): Appendix 2 compares damping, not specimens. (Until
// 2026-12-02 each set prepared its own specimen, and the three specimens'
// peaks spread by 13 %.)
//
// The full study (1000 faces, box 12 x 12 x 6 largest grains) takes hours:
// --estimate prints an estimate from the measured step rate of each sand's
// deposition, slowed for a packed specimen of faceted grains by a factor
// measured on the sub-angular run (kPackedSlowdown). --quick (a 4 x 4 x 2.6 mm box, 4 shapes of 100 faces, strains
// 6 % and 12 %) checks the chain (configs, runs, the search, study.json,
// the report), not the densities: it targets the lab's indices and skips the
// own index measurement (see base_spec). --only damping still runs
// the glass beads' run first (their indices and friction).
//
// --seeds N runs each selected sand with N seeds (7, 8, ...: other grain
// shapes from the same generator, another fill; each run measures its own
// index void ratios), in DIR/<sand> for seed 7 and DIR/<sand>-seed<S> for
// the others, so that the report can tell a trend between two sands from
// the scatter between specimens of one (a box of 1300-1700 grains).
//
// Running it again on the same DIR continues it: a run whose run.json is
// written is done and kept, a run with a checkpoint resumes from it
// (`grainlab run --resume`), and the own index void ratios are measured once
// per run folder. Each sitting is timed into DIR/<run>/study_sittings.json,
// with, while it runs, when the run last saved progress a later sitting
// reuses (its checkpoint or its index densities); a sitting that was killed counts up to
// that, so run_wall_s is the wall time of the work the run kept, however many
// sittings it took (commit an unfinished run's checkpoint with its folder).
#include "core/wait_policy.h"
#include "core/error.h"
#include "core/parallel.h"
#include "core/timer.h"
#include "dynamics/laws/registry.h"
#include "io/config.h"
#include "io/kept_preparations.h"
#include "io/json.h"
#include "lab/direct_shear.h"
#include "lab/sand_presets.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstring>
#include <condition_variable>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <string>
#include <thread>

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

using namespace grainlab;
namespace fs = std::filesystem;

namespace {

struct Options {
  bool quick = false;
  bool estimate = false;
  std::string out = "runs/study_four_sands";
  std::string grainlab;  // default: next to this program
  std::string only;
  int threads = 0;
  int seeds = 1;  // seeds per sand: 7, 8, ...
};

struct Sand {
  const char* name;    // run folder
  const char* preset;  // lab/sand_presets.h
  double final_strain;
};

// Angular grains go to 20 % (Appendix 3: critical state past 10 %).
const std::vector<Sand> kSands = {{"glass-beads", "glass-beads", 0.10},
                                  {"rounded", "ottawa", 0.10},
                                  {"sub-angular", "griffin", 0.10},
                                  {"angular", "crushed-limestone", 0.20}};

constexpr double kTargetDr = 0.9;
constexpr std::uint64_t kFirstSeed = 7;
constexpr int kMaxSeeds = 8;

// The run folder of a sand's seed: the sand's name for the first seed.
std::string run_name(const Sand& s, std::uint64_t seed) {
  return seed == kFirstSeed ? std::string(s.name) : fmt::format("{}-seed{}", s.name, seed);
}
constexpr double kDrTolerance = 0.05;

LabSpec base_spec(const Options& o, const Sand& s) {
  LabSpec spec;
  apply_sand_preset(spec, s.preset);
  if (o.quick) {
    spec.box.length = spec.box.width = 4.0e-3;
    spec.box.height = 2.6e-3;
    spec.grains.shapes = 4;
    spec.grains.faces = 100;  // the config's least
  } else {
    // 12 largest grains across, 6 high (the issue; ASTM D3080 asks 10 x 6).
    spec.box.length = spec.box.width = 12 * spec.grains.d_max;
    spec.box.height = 6 * spec.grains.d_max;
    spec.grains.shapes = 24;
    spec.grains.faces = 1000;
  }
  spec.settings<ShearSpec>().final_strain = o.quick ? 0.6 * s.final_strain : s.final_strain;
  spec.numerics.inertial_number = 9e-4;
  spec.numerics.threads = o.threads;
  spec.seed = kFirstSeed;
  // Dr 0.9 on the grains' own indices, the deposition friction found by the
  // run's bisection (the run measures the indices first).
  spec.specimen.indices = "own";
  spec.specimen.relative_density = kTargetDr;
  spec.specimen.relative_density_tolerance = kDrTolerance;
  spec.specimen.deposition_friction = -1;
  // --quick checks the chain, not the densities: the quick box's bulk (1.5
  // mean diameters from every wall) is a grain or two thick and its void
  // ratio scatters by more than the whole index range (measured: glass
  // beads, own e_min 0.583 in the index box, 0.678-0.708 in the quick box at
  // friction 0-0.01), and measuring faceted grains' own indices in the index
  // box takes over 7 minutes a sand. So it targets Dr 0.9 on the sand's lab
  // indices and takes the search's first trial.
  if (o.quick) {
    spec.specimen.indices = "lab";
    spec.specimen.tolerance = 10;
  }
  spec.output.checkpoint_interval = 600;
  spec.output.snapshot_interval = 0;
  return spec;
}

// SIGINT/SIGTERM: the running grainlab saves its checkpoint and stops; the
// study then records the sitting and stops too.
volatile std::sig_atomic_t g_stop = 0;
void on_stop(int) { g_stop = 1; }

// Runs `args` (no shell) and waits for it to exit; its exit status, or 128 +
// the signal that ended it. A stop signal to the study (g_stop) is passed on
// to it, and the study goes on waiting until it has exited: grainlab saves
// its checkpoint on SIGTERM, and the study must not count the sitting, nor
// say whether there is a checkpoint, before that is done. (Through
// std::system a stop signal to the process group ended the shell at once,
// and the study looked for the checkpoint while grainlab was still writing it.)
int run_and_wait(const std::vector<std::string>& args) {
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  pid_t pid = 0;
  if (const int e = posix_spawn(&pid, argv[0], nullptr, nullptr, argv.data(), environ); e != 0)
    input_error("cannot start '{}': {}", args[0], std::strerror(e));
  bool passed_on = false;
  int status = 0;
  for (;;) {
    if (waitpid(pid, &status, 0) == pid) break;
    if (errno != EINTR) return 127;
    if (g_stop && !passed_on) kill(pid, SIGTERM), passed_on = true;
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
}

// SIGINT and SIGTERM set g_stop and interrupt a wait (no SA_RESTART).
void catch_stop_signals() {
  struct sigaction sa {};
  sa.sa_handler = on_stop;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = 0;
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);
}

template <typename TimePoint>
double seconds_since_epoch(TimePoint t) {
  return std::chrono::duration<double>(t.time_since_epoch()).count();
}

// What a stopped run keeps in its folder: its checkpoint, its index
// densities, the index preparation and trials (index_e_min_seed7.bin,
// trial_friction_0.02990000.bin).
std::vector<fs::path> kept_files(const fs::path& folder) {
  std::vector<fs::path> kept;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(folder, ec)) {
    const std::string name = entry.path().filename().string();
    if (name == "checkpoint.bin" || name == "index_densities.json" || is_kept_preparation_file(name))
      kept.push_back(entry.path());
  }
  return kept;
}

// When the run in folder last saved progress that a later sitting reuses:
// one of its kept files (0 if none).
double last_saved(const fs::path& folder) {
  double newest = 0;
  for (const fs::path& kept : kept_files(folder)) {
    std::error_code ec;
    const auto t = fs::last_write_time(kept, ec);
    if (!ec) newest = std::max(newest, seconds_since_epoch(std::chrono::file_clock::to_sys(t)));
  }
  return newest;
}

// Wall time of the run's earlier sittings. One without an end was killed and
// counts up to the last progress it saved (`saved_until`, noted while it ran,
// not the files' times: a fresh checkout gives every file a new time).
double earlier_sittings(const nlohmann::json& sittings) {
  double total = 0;
  for (const auto& s : sittings) {
    const double start = s.at("start").get<double>();
    const double end = s.contains("end") ? s["end"].get<double>() : s.value("saved_until", start);
    total += std::max(0.0, end - start);
  }
  return total;
}

// Runs `grainlab run` on spec (written to DIR/configs/name.toml) into DIR/name,
// or resumes it from its checkpoint; a run whose run.json is written is done.
bool shear_run(const Options& o, LabSpec spec, const std::string& name, nlohmann::json& record) {
  const fs::path folder = fs::path(o.out) / name;
  spec.output.folder = folder.string();
  const fs::path config = fs::path(o.out) / "configs" / (name + ".toml");
  fs::create_directories(config.parent_path());
  std::ofstream(config) << to_toml(spec);
  const fs::path sittings_file = folder / "study_sittings.json";
  nlohmann::json sittings = fs::exists(sittings_file) ? read_json_file(sittings_file) : nlohmann::json::array();
  record["run_folder"] = name;
  const double before = earlier_sittings(sittings);
  if (fs::exists(folder / "run.json")) {
    fmt::print("  done earlier ({} sittings, {:.0f} s): {}\n", sittings.size(), before, (folder / "run.json").string());
    record["run_wall_s"] = before;
    record["sittings"] = sittings.size();
    record["run_exit_status"] = 0;
    return true;
  }
  const bool resume = fs::exists(folder / "checkpoint.bin");
  std::vector<std::string> args = {o.grainlab, "run", config.string(), "--quiet", "--no-report"};
  if (resume) args.push_back("--resume");
  std::string cmd;  // as a shell would take it
  for (const std::string& a : args) cmd += (cmd.empty() ? "'" : " '") + a + "'";
  fmt::print("  {}\n", cmd);
  std::fflush(stdout);
  fs::create_directories(folder);
  const double start = seconds_since_epoch(std::chrono::system_clock::now());
  sittings.push_back({{"start", start}});
  write_json_file(sittings_file, sittings);
  // While the run goes, note every 20 s when it last saved progress, so a
  // sitting killed with the study counts only the work it kept.
  std::mutex m;
  std::condition_variable cv;
  bool finished = false;
  // The watcher blocks the stop signals, so that they reach the thread waiting for the run.
  sigset_t stop_signals, before_watcher;
  sigemptyset(&stop_signals);
  sigaddset(&stop_signals, SIGINT);
  sigaddset(&stop_signals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &stop_signals, &before_watcher);
  std::thread watcher([&] {
    std::unique_lock lock(m);
    while (!cv.wait_for(lock, std::chrono::seconds(20), [&] { return finished; })) {
      const double saved = last_saved(folder);
      if (saved > start && saved != sittings.back().value("saved_until", 0.0)) {
        sittings.back()["saved_until"] = saved;
        write_json_file(sittings_file, sittings);
      }
    }
  });
  pthread_sigmask(SIG_SETMASK, &before_watcher, nullptr);
  Stopwatch clock;
  const int rc = run_and_wait(args);
  {
    std::lock_guard lock(m);
    finished = true;
  }
  cv.notify_one();
  watcher.join();
  // Stopped by a signal, the run kept what it saved (its checkpoint, if it
  // had reached the test, or its preparations: io/kept_preparations.h).
  const double end = g_stop ? std::max(start, last_saved(folder)) : start + clock.seconds();
  sittings.back()["end"] = end;
  write_json_file(sittings_file, sittings);
  record["run_wall_s"] = before + (end - start);
  record["sittings"] = sittings.size();
  record["run_exit_status"] = rc;
  if (g_stop) {
    fmt::print("study stopped by a signal: {}; run the same command again to continue\n",
               !kept_files(folder).empty() ? folder.string() + " goes on from what it kept"
                                           : folder.string() + " starts again (nothing kept yet)");
    record["stopped"] = true;
    return false;
  }
  return rc == 0;
}

void save(const Options& o, const nlohmann::json& study) {
  write_json_file(fs::path(o.out) / "study.json", study);
}

// What the report tabulates, from the run's run.json into the study's record;
// the spec gets the own indices and the friction the run found.
void copy_preparation(const Options& o, const std::string& name, LabSpec& spec, nlohmann::json& record) {
  const fs::path run_json = fs::path(o.out) / name / "run.json";
  if (!fs::exists(run_json)) {
    record["error"] = fmt::format("no {}: the run failed (see its messages above)", run_json.string());
    return;
  }
  const nlohmann::json run = nlohmann::json::parse(std::ifstream(run_json));
  const nlohmann::json& p = run.at("preparation");
  record["e_min"] = p.value("own_e_min", NAN);
  record["e_max"] = p.value("own_e_max", NAN);
  record["deposition_friction"] = p.value("deposition_friction", NAN);
  record["prepared_void_ratio"] = p.value("bulk_void_ratio", NAN);
  record["relative_density"] = p.value("relative_density_own", NAN);
  if (run.contains("specimen_preparation")) record["specimen_preparation"] = run["specimen_preparation"];
  if (p.contains("own_e_min") && p.contains("own_e_max")) {
    spec.specimen.own_e_min = p["own_e_min"];
    spec.specimen.own_e_max = p["own_e_max"];
  }
  spec.specimen.deposition_friction = p.at("deposition_friction");
}

// How much slower a packed specimen of faceted grains steps than the same
// grains depositing: every grain then touches about six others, and a
// touching pair of 1000-face grains costs several microseconds
// (collision/patch.cpp). Measured 2026-12-02 on the sub-angular study run,
// 2 threads: deposition 172 steps/s, consolidation and shear 31.8 steps/s
// (94,349 steps in 2967 s), the own e_min's compaction 18 steps/s (the
// machine shared with builds): about 5.4 to 10; 6 is used. Spheres slow
// down little (glass beads: 82,477 test steps in 43 s).
constexpr double kPackedSlowdown = 6;

void estimate(const Options& o) {
  Options full = o;
  full.quick = false;
  double total = 0;
  fmt::print("Estimate of the full study ({} threads, {} seed(s) a sand): each sand's deposition rate from 2000\n"
             "steps; a packed specimen of faceted grains steps {:g} times slower (see the source)\n",
             resolve_threads(o.threads), o.seeds, kPackedSlowdown);
  for (const Sand& s : kSands) {
    LabSpec spec = base_spec(full, s);
    spec.specimen.indices = "lab";  // the rate only: no index measurement, no search
    spec.specimen.deposition_friction = 0.12;
    DirectShearTest t(spec);
    Stopwatch clock;
    t.advance(2000);
    const double rate = 2000 / clock.seconds();
    const bool spheres = std::string(s.name) == "glass-beads";
    const double packed_rate = spheres ? rate : rate / kPackedSlowdown;
    const double shear_steps = spec.settings<ShearSpec>().final_strain * spec.box.length / (t.shear_speed() * t.time_step());
    // Steps measured in the sub-angular run (2026-12-02): own e_min 23,500
    // (frictionless compaction: packed), e_max 6,100 (loose deposition), three
    // trials of about 11,000 (mostly deposition), consolidation about 10,000
    // (packed), then the shear.
    const double loose_steps = 6.1e3 + 3 * 1.1e4, packed_steps = 2.35e4 + 1e4;
    const int runs = o.seeds + (spheres ? 3 : 0);  // + the damping set
    const double seconds =
        o.seeds * (loose_steps / rate + packed_steps / packed_rate) + runs * shear_steps / packed_rate;
    total += seconds;
    fmt::print("  {:<12} {:>6} grains  {:>7.0f} steps/s deposition, {:>7.0f} packed  shear {:.3g} steps x {}  ~{:.1f} h\n",
               s.name, t.world().model.bodies.size(), rate, packed_rate, shear_steps, runs, seconds / 3600);
  }
  fmt::print("total: about {:.1f} h (a lower bound where grains had not yet met in the 2000 steps timed, as\n"
             "the angular grains in their taller fill: 421 steps/s against 80 for the sub-angular ones, 2026-12-02)\n",
             total / 3600);
}

// Whether --only asks for this run: "sands" is the four sands, "damping" the
// damping set (and the glass beads it starts from), or a comma list of names.
bool selected(const Options& o, const std::string& what) {
  if (o.only.empty()) return true;
  if (o.only == "sands") return what != "damping";
  if (o.only == "damping") return what == "damping" || what == "glass-beads";
  const std::string list = "," + o.only + ",";
  return list.find("," + what + ",") != std::string::npos;
}

}  // namespace

int main(int argc, char** argv) {
  grainlab::use_passive_wait_by_default(argv);  // as grainlab runs (core/wait_policy.h)
  Options o;
  std::string run_names;  // "glass-beads, rounded, sub-angular, angular, damping"
  for (const Sand& s : kSands) run_names += s.name + std::string(", ");
  run_names += "damping";
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const bool has_value = i + 1 < argc;
    if (a == "--quick") o.quick = true;
    else if (a == "--estimate") o.estimate = true;
    else if (a == "--out" && has_value) o.out = argv[++i];
    else if (a == "--grainlab" && has_value) o.grainlab = argv[++i];
    else if (a == "--threads" && has_value) o.threads = std::stoi(argv[++i]);
    else if (a == "--only" && has_value) o.only = argv[++i];
    else if (a == "--seeds" && has_value) o.seeds = std::atoi(argv[++i]);
    else {
      fmt::print(stderr, "usage: study_four_sands [--quick] [--out DIR] [--grainlab PATH] [--threads N] "
                         "[--only sands|damping|SAND,SAND...] [--seeds N] [--estimate]\n"
                         "  SAND: {}\n", run_names);
      return 2;
    }
  }
  if (o.seeds < 1 || o.seeds > kMaxSeeds) {
    fmt::print(stderr, "study_four_sands: --seeds {}: give 1 to {} seeds per sand\n", o.seeds, kMaxSeeds);
    return 2;
  }
  if (!o.only.empty() && o.only != "sands" && o.only != "damping") {
    std::string rest = o.only + ",";
    for (std::size_t at; (at = rest.find(',')) != std::string::npos; rest.erase(0, at + 1)) {
      const std::string name = rest.substr(0, at);
      const bool known = name == "damping" || std::any_of(kSands.begin(), kSands.end(),
                                                          [&](const Sand& s) { return name == s.name; });
      if (!known) {
        fmt::print(stderr, "study_four_sands: --only '{}': no run named '{}'; the names are {}, or use sands / "
                           "damping\n", o.only, name, run_names);
        return 2;
      }
    }
  }
  catch_stop_signals();
  if (o.grainlab.empty()) o.grainlab = (fs::absolute(argv[0]).parent_path() / "grainlab").string();
  try {
    if (o.estimate) {
      estimate(o);
      return 0;
    }
    if (!fs::exists(o.grainlab)) input_error("no grainlab program at '{}': build it or pass --grainlab", o.grainlab);
    fs::create_directories(o.out);
    nlohmann::json study = {{"quick", o.quick}, {"threads", resolve_threads(o.threads)},
                            {"target_relative_density", kTargetDr}, {"sands", nlohmann::json::array()},
                            {"damping", nlohmann::json::array()}};
    Stopwatch all;
    LabSpec beads;
    bool have_beads = false;
    const auto done = [&](const Sand& s, std::uint64_t seed) {
      return fs::exists(fs::path(o.out) / run_name(s, seed) / "run.json");
    };
    const auto order = [&](const nlohmann::json& j) {
      for (std::size_t k = 0; k < kSands.size(); ++k)
        if (j.at("name") == kSands[k].name) return std::pair{k, j.value("seed", kFirstSeed)};
      return std::pair{kSands.size(), kFirstSeed};
    };
    const auto tabulate = [&](const Sand& s, std::uint64_t seed) {
      LabSpec spec = base_spec(o, s);
      spec.seed = seed;
      const std::string name = run_name(s, seed);
      nlohmann::json j = {{"name", s.name}, {"seed", seed}, {"sand_preset", s.preset},
                          {"grain_class", spec.grains.preset}};
      fmt::print("{}: {} grains of {} faces, seed {}, box {:.2f} x {:.2f} x {:.2f} mm\n", name, spec.grains.preset,
                 spec.grains.faces, seed, spec.box.length * 1e3, spec.box.width * 1e3, spec.box.height * 1e3);
      // One sand's failure leaves the others to run; the damping set needs
      // the beads' run (their indices and friction), so it runs with it.
      if (shear_run(o, spec, name, j)) copy_preparation(o, name, spec, j);
      else if (j.contains("stopped")) return;  // by a signal: the run continues in a later sitting
      else j["error"] = fmt::format("grainlab run failed (exit status {})", j["run_exit_status"].get<int>());
      if (std::string(s.name) == "glass-beads" && seed == kFirstSeed && !j.contains("error") && j.contains("e_min"))
        beads = spec, have_beads = true;
      study["sands"].push_back(j);
      std::stable_sort(study["sands"].begin(), study["sands"].end(),
                       [&](const nlohmann::json& x, const nlohmann::json& y) { return order(x) < order(y); });
      save(o, study);
    };
    // The damping runs done earlier are tabulated whatever --only says, as
    // the sands are, and before the sands still to run (hours), so that
    // study.json has them whatever becomes of this sitting.
    const auto damping_done = [&](double gn, double gt) {
      return fs::exists(fs::path(o.out) / fmt::format("damping-{:g}-{:g}", gn, gt) / "run.json");
    };
    const auto damping_set = [&](bool run_pending) {
      study["damping"] = nlohmann::json::array();
      if (run_pending && selected(o, "damping") && !have_beads)
        fmt::print("damping set skipped: it needs the glass beads' finished run (their indices and friction)\n");
      if (!(selected(o, "damping") || damping_done(40, 20)) || !have_beads) return;
      const fs::path specimen = fs::path(o.out) / "damping-40-20" / "specimen.bin";
      for (const auto& [gn, gt] : {std::pair{40.0, 20.0}, std::pair{20.0, 10.0}, std::pair{80.0, 40.0}}) {
        if (!damping_done(gn, gt) && (!run_pending || !selected(o, "damping"))) continue;
        LabSpec spec = beads;
        if (gn != 40.0) {
          if (!damping_done(gn, gt) && !fs::exists(specimen)) {
            fmt::print("damping ({:g}, {:g}) skipped: it shears the specimen of the (40, 20) run, which has none\n",
                       gn, gt);
            continue;
          }
          spec.specimen.from = specimen.string();  // relative to where the study runs, as output.folder
        }
        spec.material.law = contact_law<HertzUserLaw>();
        spec.material.grain.gamma_n = gn;
        spec.material.grain.gamma_t = gt;
        spec.specimen.relative_density_tolerance = 0.99;  // reports the density the beads' friction gives
        spec.specimen.tolerance = 10;                     // (--quick: on the lab's indices)
        nlohmann::json j = {{"gamma_n", gn}, {"gamma_t", gt}};
        const std::string name = fmt::format("damping-{:g}-{:g}", gn, gt);
        if (g_stop && !fs::exists(fs::path(o.out) / name / "run.json")) continue;  // stopped: tabulate only
        shear_run(o, spec, name, j);
        if (j.contains("stopped")) continue;
        study["damping"].push_back(j);
        save(o, study);
      }
    };
    // The runs done in earlier sittings first, selected or not, so that
    // study.json has them whatever becomes of this sitting; then the others.
    for (const Sand& s : kSands)
      for (int k = 0; k < kMaxSeeds; ++k)
        if (done(s, kFirstSeed + k)) tabulate(s, kFirstSeed + k);
    damping_set(false);
    for (const Sand& s : kSands)
      for (int k = 0; k < o.seeds; ++k)
        if (!done(s, kFirstSeed + k) && selected(o, s.name) && !g_stop) tabulate(s, kFirstSeed + k);
    damping_set(true);
    study["sitting_wall_s"] = all.seconds();  // this sitting; each run's own is its run_wall_s
    save(o, study);
    if (g_stop) return 130;  // study.json has every run done so far
    fmt::print("study done in {:.0f} s: {}/study.json; report: PYTHONPATH=build/python /usr/bin/python3 -m "
               "grainlab.report.study {}\n",
               all.seconds(), o.out, o.out);
  } catch (const std::exception& e) {
    fmt::print(stderr, "study_four_sands: {}\n", e.what());
    return 1;
  }
  return 0;
}
