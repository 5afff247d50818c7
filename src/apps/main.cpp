// grainlab: the command line.
//
//   grainlab demo [--grains N] [--spheres] [--threads N]   settling-bed demo
//
// Every subcommand explains itself with --help.
#include "core/error.h"
#include "core/parallel.h"
#include "core/timer.h"
#include "lab/settling_bed.h"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <cstdio>

using namespace grainlab;

namespace {

int run_demo(int grains, bool spheres, double seconds, std::uint64_t seed, int hull_points) {
  SettlingBedSpec spec;
  spec.hull_points = hull_points;
  spec.grains = grains;
  spec.spheres = spheres;
  spec.seed = seed;
  fmt::print("grainlab demo: settling bed of {} {} (equivalent radius {:.1f} mm, {} shapes), "
             "{} threads\n",
             grains, spheres ? "glass beads" : fmt::format("convex grains (~{}-face hulls)", 2 * hull_points - 4),
             spec.radius * 1e3, spheres ? 1 : spec.shape_count, thread_count());
  SettlingBed bed = make_settling_bed(spec);
  World& w = bed.world;
  const double dt = 0.2 * w.critical_time_step();
  const int steps = static_cast<int>(seconds / dt);
  fmt::print("time step {:.3g} s (0.2 x critical), {} steps = {:.3g} s simulated\n", dt, steps, seconds);
  Stopwatch clock;
  for (int i = 1; i <= steps; ++i) {
    w.step(dt);
    if (i % (steps / 10) == 0 || i == steps) {
      const double el = clock.seconds();
      fmt::print("  step {:6d}/{}  t = {:.4f} s  contacts {:5d}  kinetic energy {:.3e} J  "
                 "{:.0f} steps/s  ETA {:.0f} s\n",
                 i, steps, w.state.time, w.contact_count(), w.kinetic_energy(), i / el,
                 el / i * (steps - i));
      std::fflush(stdout);
    }
  }
  const double el = clock.seconds();
  fmt::print("\nsummary\n");
  fmt::print("  grains              {}\n", w.model.bodies.size());
  fmt::print("  contacts            {} ({:.2f} per grain)\n", w.contact_count(),
             2.0 * w.contact_count() / w.model.bodies.size());
  fmt::print("  steps per second    {:.0f} ({:.0f} grain-steps/s)\n", steps / el,
             steps * double(w.model.bodies.size()) / el);
  fmt::print("  final kinetic energy {:.3e} J\n", w.kinetic_energy());
  fmt::print("  max overlap         {:.3f} % of grain radius\n", 100 * max_relative_overlap(w));
  fmt::print("  all grains in box   {}\n", all_grains_inside(bed) ? "yes" : "NO");
  fmt::print("  phase times (s):   ");
  for (int p = 0; p < static_cast<int>(Phase::Count); ++p)
    fmt::print(" {} {:.2f}", kPhaseNames[p], w.profile.seconds[p]);
  fmt::print("\n");
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "grainlab: a discrete-element engine and virtual soil laboratory for realistic sand "
      "grains.\nSI units throughout (m, kg, s, N, Pa)."};
  app.require_subcommand(1);
  int threads = 0;
  app.add_option("--threads", threads, "worker threads (default: all cores)");

  auto* demo = app.add_subcommand("demo", "settle a bed of grains in a box under gravity and print a summary");
  int grains = 400;
  bool spheres = false;
  double seconds = 0.4;
  std::uint64_t seed = 1;
  demo->add_option("--grains", grains, "number of grains")->check(CLI::Range(1, 1000000));
  demo->add_flag("--spheres", spheres, "glass beads instead of convex grains");
  demo->add_option("--seconds", seconds, "simulated time (s)")->check(CLI::PositiveNumber);
  int hull_points = 1002;
  demo->add_option("--hull-points", hull_points, "vertices per convex grain hull (about 2n-4 faces)")
      ->check(CLI::Range(8, 100000));
  demo->add_option("--seed", seed, "random seed (same seed, same run)");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  set_thread_count(threads);
  try {
    if (*demo) return run_demo(grains, spheres, seconds, seed, hull_points);
  } catch (const InputError& e) {
    fmt::print(stderr, "grainlab: error: {}\n", e.what());
    return 2;
  } catch (const RunError& e) {
    fmt::print(stderr, "grainlab: run failed: {}\n", e.what());
    return 3;
  }
  return 0;
}
