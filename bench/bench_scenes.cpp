// Whole-scene benchmark: a settled dense bed of grains in a box, stepped for a
// while; prints grain-steps per second, contacts per grain and the time of each
// phase of the step, for 1 and 2 threads, and a hash of the final state (the
// same for every thread count; a speed change that keeps it kept the bits).
// Not a test: it prints figures.
//
//   build/bench_scenes [--grains N] [--settle STEPS] [--steps STEPS] [--only convex|spheres] [--threads 1|2]
// (--threads 1|2: settle and time on that many threads only, 1 for callgrind,
// whose toggled collection counts the thread that calls World::step.)
#include "bench_args.h"
#include "core/wait_policy.h"
#include "core/parallel.h"
#include "core/timer.h"
#include "lab/settling_bed.h"

#include <fmt/format.h>

#include <cstdint>
#include <cstring>
#include <string>

using namespace grainlab;

namespace {

// FNV-1a of the bodies' poses and velocities, bit for bit; without their
// orientations if `orientations` is false (a sphere's orientation enters no
// force: two builds that round it differently step the same spheres).
std::uint64_t state_hash(const World& w, bool orientations = true) {
  std::uint64_t h = 14695981039346656037ull;
  const auto mix = [&h](double v) {
    std::uint64_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    for (int k = 0; k < 8; ++k) h = (h ^ ((bits >> (8 * k)) & 0xff)) * 1099511628211ull;
  };
  for (const BodyState& b : w.state.bodies) {
    for (int k = 0; k < 3; ++k) mix(b.x[k]), mix(b.v[k]), mix(b.w[k]);
    if (orientations)
      for (int k = 0; k < 4; ++k) mix(b.q.coeffs()[k]);
  }
  return h;
}

void run_scene(const char* label, SettlingBedSpec spec, int settle, int steps, int only_threads) {
  SettlingBed bed = make_settling_bed(spec);
  World& w = bed.world;
  w.settings.threads = only_threads > 0 ? only_threads : 2;
  const double dt = 0.2 * w.critical_time_step();
  Stopwatch settle_clock;
  for (int i = 0; i < settle; ++i) w.step(dt);
  fmt::print("\n{}: {} grains, settled for {} steps ({:.1f} s wall), {:.2f} contacts per grain, "
             "KE {:.2e} J\n",
             label, w.model.bodies.size(), settle, settle_clock.seconds(),
             2.0 * w.contact_count() / w.model.bodies.size(), w.kinetic_energy());
  const World settled = w;
  for (int threads : {1, 2}) {
    if (only_threads > 0 && threads != only_threads) continue;
    World run = settled;
    run.settings.threads = threads;
    run.profile = StepProfile{};
    Stopwatch clock;
    for (int i = 0; i < steps; ++i) run.step(dt);
    const double el = clock.seconds();
    const double gs = steps * double(run.model.bodies.size()) / el;
    fmt::print("  {} thread{}: {:>10.0f} grain-steps/s  ({:.2f} ms/step, {} broadphase rebuilds, "
               "{:.0f} narrowphase pair tests and {:.0f} contacts per step; state hash {:016x}, "
               "without orientations {:016x})\n",
               threads, threads > 1 ? "s" : " ", gs, 1e3 * el / steps, run.profile.broadphase_rebuilds,
               double(run.profile.pair_tests) / steps, double(run.profile.contacts) / steps, state_hash(run),
               state_hash(run, false));
    fmt::print("     phase ms/step:");
    for (int p = 0; p < static_cast<int>(Phase::Count); ++p)
      fmt::print(" {} {:.3f}", kPhaseNames[p], 1e3 * run.profile.seconds[p] / steps);
    fmt::print("\n");
  }
}

}  // namespace

int main(int argc, char** argv) {
  const char* usage = "[--grains N] [--settle STEPS] [--steps STEPS] [--only convex|spheres] [--threads 1|2]";
  grainlab::bench::check_args(argc, argv, usage, {"--grains", "--settle", "--steps", "--only", "--threads"});
  grainlab::use_passive_wait_by_default(argv);  // as grainlab runs (core/wait_policy.h)
  int grains = 2000, settle = 10000, steps = 200, threads = 0;
  std::string only;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--grains")) grains = std::stoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--settle")) settle = std::stoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--steps")) steps = std::stoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--only")) only = argv[i + 1];
    else if (!std::strcmp(argv[i], "--threads")) threads = std::stoi(argv[i + 1]);
  }
  if (threads != 0 && threads != 1 && threads != 2) {
    fmt::print(stderr, "{}: --threads takes 1 or 2\nusage: {} {}\n", argv[0], argv[0], usage);
    return 2;
  }
  if (only != "spheres") {
    SettlingBedSpec spec;
    spec.grains = grains;
    run_scene("convex grains, ~2000-face hulls", spec, settle, steps, threads);
  }
  if (only != "convex") {
    SettlingBedSpec spec;
    spec.grains = grains;
    spec.spheres = true;
    run_scene("spheres", spec, settle, steps * 10, threads);
  }
  return 0;
}
