// The paper's specimen on this machine (issue 11 item 4): a 30 x 30 x 16 mm
// direct shear box of sub-angular grains with 2000-face hulls (about 37,000
// grains), the paper's size. Not a test: it prints figures.
//
//   build/bench_paper_size [--threads N] [--steps K] [--small MM] [--faces F]
//
// 1. Builds the full specimen as `grainlab run` does (grain library, fill
//    lattice, world) and prints its grain count, the time to build it and the
//    process's peak memory (and the lab's budget for it packed, with its
//    pairs and contacts: lab/specimen_budget.h); then times K steps of its
//    deposition (grains falling from the fill: cheaper per step than a
//    packing).
// 2. A packing under load costs more per grain: a small box of the same
//    grains (MM x MM x 8 mm, about 600 grains at 5 mm) is prepared as the
//    lab prepares one (deposition, compaction, consolidation at 100 kPa), its
//    preparation steps counted, then K steps of its shear timed: the packed
//    rate in grain-steps/s.
// 3. Projects the whole paper-size test: (preparation steps + shear steps)
//    x grains / packed rate. The shear steps are the full specimen's own
//    (10 % of 30 mm at I = 1e-3, from its time step and shear speed); the
//    preparation steps are the small box's, a lower bound (the paper's
//    specimen is twice as tall, so its grains fall further).
// Issue 11's goal: under 3 hours projected on this 2-core machine and under
// 8 GB of memory. --faces F (default 2000, the paper's scans) shows what a
// coarser grain would cost instead.
#include "bench_args.h"
#include "core/parallel.h"
#include "core/timer.h"
#include "core/wait_policy.h"
#include "lab/direct_shear.h"
#include "lab/specimen_budget.h"

#include <fmt/format.h>

#include <cstring>
#include <fstream>
#include <string>

using namespace grainlab;

namespace {

// Peak resident memory of this process so far (GB), from /proc/self/status.
double peak_memory_gb() {
  std::ifstream in("/proc/self/status");
  std::string key;
  double kb = 0;
  while (in >> key) {
    if (key == "VmHWM:") {
      in >> kb;
      break;
    }
    std::getline(in, key);
  }
  return kb / (1024.0 * 1024.0);
}

LabSpec paper_spec(int threads, int faces) {
  LabSpec spec;  // 0.707-0.841 mm, 100 kPa
  spec.grains.preset = "sub-angular";  // the paper's Griffin sand (the lab's default is rounded since 97c501d)
  spec.specimen.indices = "lab";  // Griffin's indices: the rate only, no own index measurement
  spec.specimen.deposition_friction = 0.12;  // the preparation the README's projections were timed with
  spec.grains.faces = faces;
  spec.box.length = spec.box.width = 30e-3;
  spec.box.height = 16e-3;
  spec.numerics.inertial_number = 1e-3;
  spec.numerics.threads = threads;
  spec.output.strain_interval = 0.005;
  return spec;
}

// Times `steps` steps of t (grain-steps/s).
double time_steps(DirectShearTest& t, int steps) {
  const double grains = static_cast<double>(t.world().model.bodies.size());
  Stopwatch clock;
  t.advance(steps);
  return steps * grains / std::max(clock.seconds(), 1e-9);
}

}  // namespace

int main(int argc, char** argv) {
  grainlab::bench::check_args(argc, argv, "[--threads N] [--steps K] [--small MM] [--faces F]",
                              {"--threads", "--steps", "--small", "--faces"});
  grainlab::use_passive_wait_by_default(argv);  // as grainlab runs (core/wait_policy.h)
  int threads = 0, steps = 200, faces = 2000;
  double small = 5.0;
  for (int i = 1; i < argc; ++i) {
    const bool value = i + 1 < argc;
    if (!std::strcmp(argv[i], "--threads") && value) threads = std::stoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--steps") && value) steps = std::stoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--small") && value) small = std::stod(argv[++i]);
    else if (!std::strcmp(argv[i], "--faces") && value) faces = std::stoi(argv[++i]);
  }
  threads = resolve_threads(threads);

  // 1. The full specimen.
  const LabSpec full = paper_spec(threads, faces);
  Stopwatch build_clock;
  DirectShearTest paper(full);
  const double build_s = build_clock.seconds();
  const double grains = static_cast<double>(paper.world().model.bodies.size());
  fmt::print("paper-size specimen: {:.0f} x {:.0f} x {:.0f} mm, {:.0f} {} grains of {} faces, {} thread{}\n",
             1e3 * full.box.length, 1e3 * full.box.width, 1e3 * full.box.height, grains, full.grains.preset,
             full.grains.faces,
             threads, threads > 1 ? "s" : "");
  fmt::print("  built in {:.1f} s; dt {:.3g} s, shear speed {:.3g} mm/s\n", build_s, paper.time_step(),
             1e3 * paper.shear_speed());
  const double deposit_rate = time_steps(paper, steps);
  fmt::print("  {} deposition steps (falling grains): {:.3g} grain-steps/s; peak memory so far {:.2f} GB (no "
             "contacts yet; packed, with its pairs and contacts, the lab's budget is {:.2f} GB)\n",
             steps, deposit_rate, peak_memory_gb(), grains * bytes_per_grain() / 1e9);
  std::fflush(stdout);
  const double shear_steps =
      full.settings<ShearSpec>().final_strain * full.box.length / (paper.shear_speed() * paper.time_step());

  // 2. A small box of the same grains, prepared, then sheared.
  LabSpec box = full;
  box.box.length = box.box.width = small * 1e-3;
  box.box.height = 8e-3;
  auto preparation = std::make_unique<SpecimenPreparation>(box);
  preparation->accept_any_density();  // the rate is wanted, whatever density the preparation reaches
  DirectShearTest t(box, std::move(preparation));
  Stopwatch prep_clock;
  while (!t.loading() && !t.done()) t.advance(2000);
  const double prep_s = prep_clock.seconds();
  std::fflush(stdout);
  const double prep_steps = static_cast<double>(t.world().state.step);
  const double small_grains = static_cast<double>(t.world().model.bodies.size());
  const double shear_rate = time_steps(t, steps);
  fmt::print("small box {:.1f} x {:.1f} x 8 mm, {:.0f} grains: prepared in {:.0f} steps ({:.0f} s, e {:.3f}); "
             "{} shear steps: {:.3g} grain-steps/s\n",
             small, small, small_grains, prep_steps, prep_s, t.achieved_void_ratio(), steps, shear_rate);

  // 3. The projection.
  const double hours = (prep_steps + shear_steps) * grains / shear_rate / 3600;
  fmt::print("projected paper-size test (preparation {:.3g} steps, a lower bound, + shear to {:.0f} % {:.3g} steps) "
             "x {:.0f} grains at {:.3g} grain-steps/s: {:.1f} h on {} thread{} (goal: under 3 h); "
             "memory about {:.2f} GB packed (goal: under 8 GB)\n",
             prep_steps, 100 * full.settings<ShearSpec>().final_strain, shear_steps, grains, shear_rate, hours, threads,
             threads > 1 ? "s" : "", grains * bytes_per_grain() / 1e9);
  return 0;
}
