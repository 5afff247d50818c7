// `grainlab grains index`: the grains' own index void ratios e_min and e_max
// (method in lab/index_densities.h), printed with their spread over seeds and
// as the two config lines that let `grainlab run` skip the measurement.
#include "apps/commands.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/timer.h"
#include "io/config.h"
#include "io/json.h"
#include "io/kept_preparations.h"
#include "io/preparation_files.h"
#include "lab/index_densities.h"

#include <fmt/format.h>

#include <atomic>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

namespace grainlab::apps {

namespace {

std::atomic<int> g_index_stop{0};
extern "C" void on_index_stop(int sig) { g_index_stop = sig; }

struct IndexOptions {
  std::string config;
  std::string preset, folder;
  int shapes = 0, faces = 0;
  double d_min = 0, d_max = 0, stress = 0;
  std::uint64_t seed = 0;
  int threads = 0;
  std::string json;
  std::string keep;  // folder that keeps the preparations (--keep)
  IndexDensityOptions measure;
};

int run_index(const IndexOptions& o) {
  LabSpec spec = o.config.empty() ? LabSpec{} : load_config(o.config);
  if (!o.preset.empty()) spec.grains.preset = o.preset, spec.grains.folder.clear();
  if (!o.folder.empty()) spec.grains.folder = o.folder;
  if (o.shapes > 0) spec.grains.shapes = o.shapes;
  if (o.faces > 0) spec.grains.faces = o.faces;
  if (o.d_min > 0) spec.grains.d_min = o.d_min;
  if (o.d_max > 0) spec.grains.d_max = o.d_max;
  if (spec.grains.d_max <= spec.grains.d_min)
    input_error("--d-max {} must be larger than --d-min {} (m)", spec.grains.d_max, spec.grains.d_min);
  if (o.stress > 0) spec.consolidation.normal_stress = o.stress;
  if (o.seed > 0) spec.seed = o.seed;
  spec.numerics.threads = o.threads;
  if (!o.json.empty()) check_file_target(o.json);  // before minutes of work, not after
  fmt::print("grainlab grains index: {} ({} shapes, {} faces, sieve {:.3f}-{:.3f} mm), box {:g} x {:g} x {:g} "
             "d_max, {} seeds, compaction at {:.0f} kPa, loose deposition friction {:g}\n",
             spec.grains.folder.empty() ? spec.grains.preset : spec.grains.folder, spec.grains.shapes,
             spec.grains.faces, spec.grains.d_min * 1e3, spec.grains.d_max * 1e3, o.measure.box_diameters,
             o.measure.box_diameters, o.measure.height_diameters, o.measure.seeds,
             spec.consolidation.normal_stress * 1e-3, o.measure.loose_friction);
  std::fflush(stdout);
  // --keep: the preparations done (FOLDER/index_densities.json) and the one
  // under way (FOLDER/index_e_min_seedN.bin, io/kept_preparations.h).
  namespace fs = std::filesystem;
  IndexDensities done;
  std::unique_ptr<KeptPreparations> store;
  const fs::path record = o.keep.empty() ? fs::path() : fs::path(o.keep) / "index_densities.json";
  if (!o.keep.empty()) {
    done = unfinished_index_densities(record, spec);
    const auto finished = cached_index_densities(record, spec);
    if (!done.dense.empty() || finished) {
      const nlohmann::json j = read_json_file(record);
      const double L = o.measure.box_diameters * spec.grains.d_max, H = o.measure.height_diameters * spec.grains.d_max;
      bool same = std::abs(j.value("box_length_m", 0.0) - L) <= 1e-9 * L &&
                  std::abs(j.value("box_height_m", 0.0) - H) <= 1e-9 * H;
      for (const IndexPreparation& p : done.loose) same = same && p.friction == o.measure.loose_friction;
      if (!same)
        input_error("--keep {}: its index_densities.json holds preparations of another box or loose friction "
                    "(box {:.4g} x {:.4g} m, this measurement {:.4g} x {:.4g} m); give another --keep folder, or "
                    "remove that file to start again",
                    o.keep, j.value("box_length_m", 0.0), j.value("box_height_m", 0.0), L, H);
      if (finished) {
        fmt::print("{} already holds this measurement: e_min = {:.4f}, e_max = {:.4f} (remove it to measure "
                   "again)\nfor the run config:\n[specimen]\nown_e_min = {:.4f}\nown_e_max = {:.4f}\n",
                   record.string(), finished->first, finished->second, finished->first, finished->second);
        return 0;
      }
      fmt::print("  keeping the {} preparation(s) done before, from {}\n", done.dense.size() + done.loose.size(),
                 record.string());
    }
    fs::create_directories(o.keep);
    store = std::make_unique<KeptPreparations>(o.keep, [] { return g_index_stop != 0; });
    for (const int sig : {SIGINT, SIGTERM, SIGHUP, SIGXFSZ}) std::signal(sig, on_index_stop);
  }
  Stopwatch clock;
  IndexDensities d;
  try {
    d = measure_index_densities(
        spec, o.measure,
        [](const std::string& line) {
          fmt::print("  {}\n", line);
          std::fflush(stdout);
        },
        std::move(done),
        [&](const IndexDensities& so_far) {
          if (!record.empty()) write_index_densities(record, spec, so_far, false);
        },
        store.get());
  } catch (const Stopped& e) {
    fmt::print("stopped by signal {}: {}; the same command goes on from {}\n", g_index_stop.load(), e.what(), o.keep);
    return 130;
  }
  if (!record.empty()) write_index_densities(record, spec, d);
  fmt::print("e_min = {:.4f} (spread {:.4f} over {} seeds), e_max = {:.4f} (spread {:.4f}); {} grains per "
             "preparation, {:.0f} s\n",
             d.e_min, d.e_min_spread, o.measure.seeds, d.e_max, d.e_max_spread, d.grains, clock.seconds());
  if (!d.settled())
    fmt::print("warning: some preparations reached the step cap (--max-steps) before they came to rest; "
               "the figures are what they reached\n");
  fmt::print("for the run config:\n[specimen]\nown_e_min = {:.4f}\nown_e_max = {:.4f}\n", d.e_min, d.e_max);
  if (!o.json.empty()) {
    write_index_densities(o.json, spec, d);
    fmt::print("wrote {}\n", o.json);
  }
  return 0;
}

}  // namespace

Command add_grains_index_command(CLI::App& grains) {
  auto o = std::make_shared<IndexOptions>();
  auto* cmd = grains.add_subcommand(
      "index",
      "measure the grains' own index void ratios, e_min (densest) and e_max (loosest), the way grainlab\n"
      "prepares specimens, so that a target relative density Dr = (e_max - e)/(e_max - e_min) means the same\n"
      "for any grains (the lab's e_min/e_max of a real sand need not hold for synthetic grains).\n"
      "  e_min: deposition under 100 g (times the density scaling) without friction, then compaction under\n"
      "         the cap at the consolidation stress (default 100 kPa), still without friction;\n"
      "  e_max: deposition with friction --loose-friction (default 1.0), no compaction, no cap.\n"
      "Box: --box-diameters x d_max square (at least 10 for index values), --height-diameters x d_max high,\n"
      "lubricated walls. The void ratio is measured in the bulk, 1.5 mean diameters away from the walls,\n"
      "the floor and the cap (2.5 below the highest grain without a cap): walls loosen the layer that\n"
      "touches them. Each index is the mean over --seeds preparations; the spread (max - min) is printed.\n"
      "Units: SI (metres, pascals). Time: about 1000 grains per preparation; spheres (glass-beads) take\n"
      "about a minute per preparation on 2 cores, faceted grains several (frictionless faceted grains may\n"
      "not come to rest: --max-steps caps each preparation and the result says so).\n"
      "Prints the two lines own_e_min/own_e_max for the [specimen] table of a run config.");
  cmd->add_option("--config", o->config, "take grains, material, consolidation stress, numerics and seed from this "
                                         "run config (TOML); the options below override it");
  cmd->add_option("--preset", o->preset,
                  "grain class: glass-beads | rounded | sub-angular | angular, or a spherical-harmonic sand: "
                  "sh-ottawa | sh-river | sh-limestone")
      ->check(CLI::IsMember({"glass-beads", "rounded", "sub-angular", "angular", "sh-ottawa", "sh-river",
                             "sh-limestone"}));
  cmd->add_option("--folder", o->folder, "import the grains of this folder instead (meshes: STL/OBJ/PLY; SH files: .dat)");
  cmd->add_option("--shapes", o->shapes, "distinct grain shapes (default: the config's, 24)")->check(CLI::PositiveNumber);
  cmd->add_option("--faces", o->faces, "faces per grain shape (default: the config's, 200)")->check(CLI::Range(100, 1000000));
  cmd->add_option("--d-min", o->d_min, "smallest sieve size, m (default 0.707e-3)")->check(CLI::PositiveNumber);
  cmd->add_option("--d-max", o->d_max, "largest sieve size, m (default 0.841e-3)")->check(CLI::PositiveNumber);
  cmd->add_option("--stress", o->stress, "compaction stress of e_min, Pa (default: consolidation.normal_stress, 100e3)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--seed", o->seed, "first seed (default: the config's, 1); seeds seed, seed + 1, ...");
  cmd->add_option("--seeds", o->measure.seeds, "preparations per index")->check(CLI::Range(1, 100))->capture_default_str();
  cmd->add_option("--box-diameters", o->measure.box_diameters, "box side in d_max")
      ->check(CLI::Range(4.0, 1000.0))
      ->capture_default_str();
  cmd->add_option("--height-diameters", o->measure.height_diameters, "specimen height in d_max")
      ->check(CLI::Range(4.0, 1000.0))
      ->capture_default_str();
  cmd->add_option("--loose-friction", o->measure.loose_friction, "deposition friction of e_max")
      ->check(CLI::Range(0.0, 10.0))
      ->capture_default_str();
  cmd->add_option("--max-steps", o->measure.max_steps, "step cap per preparation phase (at most 399000)")
      ->check(CLI::Range(1000, 399000))
      ->capture_default_str();
  cmd->add_option("--threads", o->threads, "worker threads; 0 = automatic (up to all cores, timed)")
      ->capture_default_str();
  cmd->add_option("--json", o->json, "also write the figures, every preparation, to this JSON file");
  cmd->add_option("--keep", o->keep,
                  "keep the preparations in this folder as they run (the one under way every 600 s and on Ctrl-C, "
                  "those done in its index_densities.json): the same command goes on from them");
  return [cmd, o]() { return *cmd ? run_index(*o) : -1; };
}

}  // namespace grainlab::apps
