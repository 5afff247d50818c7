// `grainlab demo`: settles a bed of grains in a box and prints a summary.
#include "apps/commands.h"
#include "core/parallel.h"
#include "core/timer.h"
#include "lab/settling_bed.h"

#include <fmt/format.h>

#include <cstdio>
#include <memory>

namespace grainlab::apps {

namespace {

struct DemoOptions {
  int grains = 400;
  bool spheres = false;
  double seconds = 0.4;
  std::uint64_t seed = 1;
  int hull_points = 1002;
};

int run_demo(const DemoOptions& o) {
  SettlingBedSpec spec;
  spec.grains = o.grains;
  spec.spheres = o.spheres;
  spec.seed = o.seed;
  spec.hull_points = o.hull_points;
  fmt::print("grainlab demo: settling bed of {} {} (equivalent radius {:.1f} mm, {} shapes), "
             "{} threads\n",
             o.grains, o.spheres ? "glass beads" : fmt::format("convex grains (~{}-face hulls)", 2 * o.hull_points - 4),
             spec.radius * 1e3, o.spheres ? 1 : spec.shape_count, thread_count());
  SettlingBed bed = make_settling_bed(spec);
  World& w = bed.world;
  const double dt = 0.2 * w.critical_time_step();
  const int steps = std::max(1, static_cast<int>(o.seconds / dt));
  fmt::print("time step {:.3g} s (0.2 x critical), {} steps = {:.3g} s simulated\n", dt, steps, o.seconds);
  Stopwatch clock;
  const int report_every = std::max(1, steps / 10);
  for (int i = 1; i <= steps; ++i) {
    w.step(dt);
    if (i % report_every == 0 || i == steps) {
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
  fmt::print("  grains               {}\n", w.model.bodies.size());
  fmt::print("  contacts             {} ({:.2f} per grain)\n", w.contact_count(),
             2.0 * w.contact_count() / w.model.bodies.size());
  fmt::print("  steps per second     {:.0f} ({:.0f} grain-steps/s)\n", steps / el,
             steps * double(w.model.bodies.size()) / el);
  fmt::print("  final kinetic energy {:.3e} J\n", w.kinetic_energy());
  fmt::print("  max overlap          {:.3f} % of grain radius\n", 100 * max_relative_overlap(w));
  fmt::print("  all grains in box    {}\n", all_grains_inside(bed) ? "yes" : "NO");
  fmt::print("  phase times (s):    ");
  for (int p = 0; p < static_cast<int>(Phase::Count); ++p)
    fmt::print(" {} {:.2f}", kPhaseNames[p], w.profile.seconds[p]);
  fmt::print("\n");
  return 0;
}

}  // namespace

Command add_demo_command(CLI::App& app) {
  auto o = std::make_shared<DemoOptions>();
  auto* demo = app.add_subcommand("demo", "settle a bed of grains in a box under gravity and print a summary");
  demo->add_option("--grains", o->grains, "number of grains")->check(CLI::Range(1, 1000000));
  demo->add_flag("--spheres", o->spheres, "glass beads instead of convex grains");
  demo->add_option("--seconds", o->seconds, "simulated time (s)")->check(CLI::PositiveNumber);
  demo->add_option("--hull-points", o->hull_points, "vertices per convex grain hull (about 2n-4 faces)")
      ->check(CLI::Range(8, 100000));
  demo->add_option("--seed", o->seed, "random seed (same seed, same run)");
  return [demo, o]() { return *demo ? run_demo(*o) : -1; };
}

}  // namespace grainlab::apps
