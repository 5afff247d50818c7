// Preparation that reaches what it is asked (issue 10 item 3): for each
// grain class (the four sand presets, or a folder of imported meshes), the
// grains' own index void ratios are measured (lab/index_densities.h, one
// seed, as `grainlab run` does) and the deposition friction is searched
// (lab/preparation_search.h) for each target Dr on those indices. Prints
// every trial (friction, bulk e, Dr) and one table: target, reached Dr,
// friction, trials, the trials' wall time (one thread; a kept trial counts
// its earlier sittings), or why the search stopped. Not a test: it
// prints figures (minutes per preparation of 200-face grains).
//
//   build/bench_preparation_range [--sands glass-beads,ottawa,griffin,crushed-limestone]
//       [--folder DIR] [--targets 0.2,0.6,0.95] [--faces 200] [--seed 1]
//       [--threads 1] [--max-friction 5] [--out runs/preparation_range]
//
// The box is the demo's (8.5 x 8.5 x 5.1 mm, 10 d_max across), the grains
// 0.707-0.841 mm. Everything a preparation makes is kept under
// OUT/<class>/ (index_densities.json, index_*.bin, trial_friction_*.bin,
// every 10 minutes and at each preparation's end): a killed run goes on
// from there when started again (the target sets the grain count, so each
// target's trials are its own). The imported grains of docs/direct_shear.md are 24
// grains segmented from a synthetic CT scan:
//   grainlab ct synth --out scan.nrrd --size 200 --grains 24 --touching 4 --seed 5
//   grainlab ct segment scan.nrrd --out ct_grains   (then --folder ct_grains)
#include "core/error.h"
#include "core/timer.h"
#include "io/kept_preparations.h"
#include "io/preparation_files.h"
#include "lab/index_densities.h"
#include "lab/preparation_search.h"
#include "lab/sand_presets.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

using namespace grainlab;
namespace fs = std::filesystem;

namespace {

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string item; std::getline(in, item, ',');)
    if (!item.empty()) out.push_back(item);
  return out;
}

struct Row {
  std::string grains;
  double target = 0, reached = NAN, friction = NAN, wall_s = 0;
  std::size_t trials = 0;
  std::string why;  // empty when reached
};

void say(const std::string& line) {
  fmt::print("  {}\n", line);
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  std::setvbuf(stdout, nullptr, _IOLBF, 0);  // a line at a time into a log
  std::vector<std::string> sands = sand_preset_names();
  std::vector<double> targets = {0.2, 0.6, 0.95};
  std::string folder, out = "runs/preparation_range";
  int faces = 200, threads = 1;
  double max_friction = kLoosestSearchFriction;
  std::uint64_t seed = 1;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const bool has_value = i + 1 < argc;
    if (a == "--help" || a == "-h" || !has_value) {
      fmt::print("usage: {} [--sands a,b] [--folder DIR] (--sands "" with --folder: the folder alone) [--targets 0.2,0.6,0.95] [--faces 200] [--seed 1] "
                 "[--threads 1] [--max-friction 5] [--out DIR]\n(sands: {})\n",
                 argv[0], fmt::join(sand_preset_names(), ", "));
      return a == "--help" || a == "-h" ? 0 : 2;
    }
    const std::string v = argv[++i];
    if (a == "--sands") sands = split(v);
    else if (a == "--folder") folder = v;
    else if (a == "--targets") {
      targets.clear();
      for (const std::string& t : split(v)) targets.push_back(std::stod(t));
    } else if (a == "--faces") faces = std::atoi(v.c_str());
    else if (a == "--seed") seed = std::strtoull(v.c_str(), nullptr, 10);
    else if (a == "--threads") threads = std::atoi(v.c_str());
    else if (a == "--max-friction") max_friction = std::stod(v);
    else if (a == "--out") out = v;
    else {
      fmt::print(stderr, "unknown option {} (see --help)\n", a);
      return 2;
    }
  }
  std::vector<std::string> classes = sands;
  if (!folder.empty()) classes.push_back(folder);

  std::vector<Row> rows;
  try {
    for (const std::string& c : classes) {
      LabSpec spec;
      const bool imported = c == folder;
      if (imported) {
        spec.grains.folder = folder;
      } else {
        apply_sand_preset(spec, c);
      }
      spec.grains.faces = faces;
      spec.seed = seed;
      spec.numerics.threads = threads;
      spec.specimen.indices = "own";
      const std::string name = imported ? "imported" : c;
      const fs::path dir = fs::path(out) / name;
      fs::create_directories(dir);
      fmt::print("{}: {} faces, seed {}, box {:.1f} x {:.1f} x {:.1f} mm\n", name, faces, seed, spec.box.length * 1e3,
                 spec.box.width * 1e3, spec.box.height * 1e3);
      KeptPreparations store(dir);
      const fs::path cache = dir / "index_densities.json";
      Stopwatch clock;
      if (const auto known = cached_index_densities(cache, spec)) {
        std::tie(spec.specimen.own_e_min, spec.specimen.own_e_max) = *known;
      } else {
        IndexDensityOptions o;
        o.seeds = 1;
        const IndexDensities d = measure_index_densities(spec, o, say, unfinished_index_densities(cache, spec),
                                                         [&](const IndexDensities& so_far) {
                                                           write_index_densities(cache, spec, so_far, false);
                                                         },
                                                         &store);
        write_index_densities(cache, spec, d);
        spec.specimen.own_e_min = d.e_min;
        spec.specimen.own_e_max = d.e_max;
      }
      fmt::print("{}: own e_min {:.4f}, e_max {:.4f} ({:.0f} s)\n", name, spec.specimen.own_e_min,
                 spec.specimen.own_e_max, clock.seconds());
      for (double dr : targets) {
        Row row;
        row.grains = name;
        row.target = dr;
        LabSpec s = spec;
        s.specimen.relative_density = dr;
        s.specimen.deposition_friction = -1;
        fmt::print("{}: target Dr {:.2f}\n", name, dr);
        const Stopwatch search;
        PreparationSearchOptions o;
        o.store = &store;
        o.max_friction = max_friction;
        try {
          const Preparation p = prepare_to_target(s, o, say);
          row.reached = p.specimen->achieved_own_relative_density();
          row.friction = p.friction;
          row.trials = p.trials.size();
          row.wall_s = 0;  // the trials' own times (a kept trial's earlier sittings included)
          for (const PreparationTrial& t : p.trials) row.wall_s += t.wall_s;
        } catch (const RunError& e) {
          row.why = e.what();
          row.wall_s = search.seconds();
          fmt::print("  stopped: {}\n", row.why);
        }
        rows.push_back(row);
        std::fflush(stdout);
      }
    }
  } catch (const std::exception& e) {
    fmt::print(stderr, "error: {}\n", e.what());
    return 1;
  }
  fmt::print("\n{:<20} {:>9} {:>9} {:>10} {:>7} {:>8}\n", "grains", "target", "reached", "friction", "trials",
             "wall s");
  for (const Row& r : rows)
    fmt::print("{:<20} {:>9.2f} {:>9.3f} {:>10.4f} {:>7} {:>8.0f}{}\n", r.grains, r.target, r.reached, r.friction,
               r.trials, r.wall_s, r.why.empty() ? "" : "  (not reached: see above)");
  return 0;
}
