// The 2000-bead direct shear of issue 11, timed per phase on 1 and 2 threads
// and with the count left to grainlab (threads = 0: timed as it runs,
// core/thread_tuner.h):
// glass beads 0.707-0.841 mm in an 11.39 x 11.39 x 6.0 mm box (about 2000
// beads at e = 0.6), E = 4 GPa, nu = 0.25, restitution 0.5, friction 0.12,
// frictionless lubricated walls, dt = 4.674e-7 s, no density scaling, shear
// at inertial number 1e-3 to 10 % strain, 100 kPa. This is the test the
// established sphere codes run at about 2e6 particle-steps/s per core. Not a
// test: it prints figures (particle-steps/s of each phase, the step's phase
// times during the shear, wall times).
//
//   build/bench_sphere_lab [--strain S] [--threads N]   (default: 0.10; 1, 2, then 0 = automatic)
#include "bench_args.h"
#include "core/thread_tuner.h"
#include "core/timer.h"
#include "core/wait_policy.h"
#include "lab/direct_shear.h"
#include "lab/sand_presets.h"

#include <fmt/format.h>

#include <cstring>
#include <map>
#include <string>
#include <vector>

using namespace grainlab;

namespace {

LabSpec bead_spec(double strain, int threads) {
  LabSpec spec;
  apply_sand_preset(spec, "glass-beads");
  spec.material.grain.poisson_ratio = 0.25;
  spec.material.grain.restitution = 0.5;
  spec.material.grain.friction = 0.12;
  spec.material.wall_friction = 0;
  spec.box.length = spec.box.width = 11.39e-3;
  spec.box.height = 6.0e-3;
  spec.specimen.void_ratio = 0.6;
  spec.specimen.tolerance = 1.0;  // time whatever density the preparation reaches
  spec.specimen.deposition_friction = 0.12;  // the preparation the README's figures were timed with
  spec.numerics.time_step = 4.674e-7;
  spec.numerics.density_scaling = 1;
  spec.numerics.inertial_number = 1e-3;
  spec.numerics.threads = threads;
  spec.settings<ShearSpec>().final_strain = strain;
  spec.output.strain_interval = 0.005;
  return spec;
}

void run(double strain, int threads) {
  const LabSpec spec = bead_spec(strain, threads);
  Stopwatch total;
  DirectShearTest t(spec);
  const double beads = static_cast<double>(t.world().model.bodies.size());
  fmt::print("\n{} beads, {}, dt {:.4g} s\n", beads, grainlab::thread_count_label(threads), t.time_step());
  std::string phase = t.phase_name();
  std::int64_t phase_step = t.world().state.step;
  Stopwatch clock;
  const auto report = [&] {
    const double s = clock.seconds();
    const auto steps = t.world().state.step - phase_step;
    fmt::print("  {:<12} {:>8} steps {:>8.1f} s  {:>10.3g} particle-steps/s\n", phase, steps, s,
               steps * beads / std::max(s, 1e-9));
    std::fflush(stdout);
  };
  bool shear_profiled = false;
  while (t.advance(2000)) {
    if (t.phase_name() == phase) continue;
    report();
    phase = t.phase_name();
    phase_step = t.world().state.step;
    clock = Stopwatch();
    if (phase == "shear") {
      t.world().profile = StepProfile{};
      shear_profiled = true;
    }
  }
  report();
  if (shear_profiled) {
    const StepProfile& p = t.world().profile;
    const double steps = static_cast<double>(t.world().state.step - t.loading_start_step());
    fmt::print("  shear phase ms/step:");
    for (int k = 0; k < static_cast<int>(Phase::Count); ++k)
      fmt::print(" {} {:.3f}", kPhaseNames[k], 1e3 * p.seconds[k] / steps);
    fmt::print("\n  shear: {:.0f} narrowphase pair tests and {:.0f} contacts per step\n", p.pair_tests / steps,
               p.contacts / steps);
  }
  fmt::print("  total {:.1f} s (e = {:.3f})\n", total.seconds(), t.achieved_void_ratio());
  if (threads == 0)
    fmt::print("  automatic threads: {} trials, the last chose {}\n", t.world().thread_tuner().trials(),
               t.world().thread_tuner().chosen());
}

}  // namespace

int main(int argc, char** argv) {
  grainlab::bench::check_args(argc, argv, "[--strain S] [--threads N]   (default: 0.10; 1, 2, then 0 = automatic)",
                              {"--strain", "--threads"});
  grainlab::use_passive_wait_by_default(argv);  // as grainlab runs (core/wait_policy.h)
  double strain = 0.10;
  std::vector<int> threads{1, 2, 0};
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--strain") && i + 1 < argc) {
      strain = std::stod(argv[++i]);
    } else if (!std::strcmp(argv[i], "--threads") && i + 1 < argc) {
      threads = {std::stoi(argv[++i])};
    }
  }
  for (const int n : threads) run(strain, n);
  return 0;
}
