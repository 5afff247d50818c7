// Whole-scene benchmark: a settled dense bed of grains in a box, stepped for a
// while; prints grain-steps per second, contacts per grain and the time of each
// phase of the step, for 1 and 2 threads. Not a test: it prints figures.
//
//   build/bench_scenes [--grains N] [--settle STEPS] [--steps STEPS] [--only convex|spheres]
#include "bench_args.h"
#include "core/wait_policy.h"
#include "core/parallel.h"
#include "core/timer.h"
#include "lab/settling_bed.h"

#include <fmt/format.h>

#include <cstring>
#include <string>

using namespace grainlab;

namespace {

void run_scene(const char* label, SettlingBedSpec spec, int settle, int steps) {
  SettlingBed bed = make_settling_bed(spec);
  World& w = bed.world;
  w.settings.threads = 2;
  const double dt = 0.2 * w.critical_time_step();
  Stopwatch settle_clock;
  for (int i = 0; i < settle; ++i) w.step(dt);
  fmt::print("\n{}: {} grains, settled for {} steps ({:.1f} s wall), {:.2f} contacts per grain, "
             "KE {:.2e} J\n",
             label, w.model.bodies.size(), settle, settle_clock.seconds(),
             2.0 * w.contact_count() / w.model.bodies.size(), w.kinetic_energy());
  const World settled = w;
  for (int threads : {1, 2}) {
    World run = settled;
    run.settings.threads = threads;
    run.profile = StepProfile{};
    Stopwatch clock;
    for (int i = 0; i < steps; ++i) run.step(dt);
    const double el = clock.seconds();
    const double gs = steps * double(run.model.bodies.size()) / el;
    fmt::print("  {} thread{}: {:>10.0f} grain-steps/s  ({:.2f} ms/step, {} broadphase rebuilds, "
               "{:.0f} narrowphase pair tests and {:.0f} contacts per step)\n",
               threads, threads > 1 ? "s" : " ", gs, 1e3 * el / steps, run.profile.broadphase_rebuilds,
               double(run.profile.pair_tests) / steps, double(run.profile.contacts) / steps);
    fmt::print("     phase ms/step:");
    for (int p = 0; p < static_cast<int>(Phase::Count); ++p)
      fmt::print(" {} {:.3f}", kPhaseNames[p], 1e3 * run.profile.seconds[p] / steps);
    fmt::print("\n");
  }
}

}  // namespace

int main(int argc, char** argv) {
  grainlab::bench::check_args(argc, argv, "[--grains N] [--settle STEPS] [--steps STEPS] [--only convex|spheres]",
                              {"--grains", "--settle", "--steps", "--only"});
  grainlab::use_passive_wait_by_default(argv);  // as grainlab runs (core/wait_policy.h)
  int grains = 2000, settle = 10000, steps = 200;
  std::string only;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--grains")) grains = std::stoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--settle")) settle = std::stoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--steps")) steps = std::stoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--only")) only = argv[i + 1];
  }
  if (only != "spheres") {
    SettlingBedSpec spec;
    spec.grains = grains;
    run_scene("convex grains, ~2000-face hulls", spec, settle, steps);
  }
  if (only != "convex") {
    SettlingBedSpec spec;
    spec.grains = grains;
    spec.spheres = true;
    run_scene("spheres", spec, settle, steps * 10);
  }
  return 0;
}
