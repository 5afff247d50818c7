// What a step of a run costs from a saved state, and what state it leaves:
// loads a run's config and one of its checkpoints (`grainlab run` writes
// output.folder/checkpoint.bin every output.checkpoint_interval seconds and
// when stopped), steps the test --steps steps on one thread and prints the
// CPU time per step, the collision counters and an FNV-1a hash of every
// body's pose and velocity. Two builds that print the same hash from the same
// checkpoint simulated the same thing bit for bit; what they spent per step
// (CPU seconds, or `perf stat -e instructions:u` around the bench, less the
// set-up the bench prints) is what the change saved. Not a test: the set-up
// alone decomposes the grains (about a minute for 24 SH shapes).
//
//   build/bench_sh_steps CONFIG CHECKPOINT [--steps 500]
#include "bench_args.h"
#include "io/checkpoint.h"
#include "io/config.h"
#include "lab/lab_test.h"

#include <fmt/format.h>

#include <cstdlib>
#include <cstring>
#include <ctime>
#include <span>
#include <string>
#include <vector>

using namespace grainlab;

namespace {

double cpu_seconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

std::uint64_t state_hash(const State& s) {
  std::vector<std::uint8_t> bytes;
  const auto put = [&](const auto& v) {
    const auto* p = reinterpret_cast<const std::uint8_t*>(v.data());
    bytes.insert(bytes.end(), p, p + sizeof(double) * v.size());
  };
  for (const BodyState& b : s.bodies) {
    put(b.x);
    put(b.q.coeffs());
    put(b.v);
    put(b.w);
  }
  return fnv1a64(std::span(bytes.data(), bytes.size()));
}

}  // namespace

int main(int argc, char** argv) {
  bench::check_args(argc, argv, "CONFIG CHECKPOINT [--steps 500]", {"--steps"}, {}, 3);
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s CONFIG CHECKPOINT [--steps 500]\n", argv[0]);
    return 2;
  }
  int steps = 500;
  for (int i = 3; i + 1 < argc; ++i)
    if (!std::strcmp(argv[i], "--steps")) steps = std::atoi(argv[i + 1]);
  try {
    LabSpec spec = load_config(argv[1]);
    spec.numerics.threads = 1;
    const double t0 = cpu_seconds();
    auto test = make_lab_test(spec.test, spec);
    Checkpoint ck = load_checkpoint(argv[2]);
    test->world().state = std::move(ck.state);
    test->load(ck.protocol);
    const double t1 = cpu_seconds();
    const std::int64_t first = test->world().state.step;
    test->world().profile = {};
    while (test->world().state.step - first < steps && !test->done())
      test->advance(static_cast<int>(steps - (test->world().state.step - first)));
    const double t2 = cpu_seconds();
    const StepProfile& p = test->world().profile;
    const std::int64_t done = test->world().state.step - first;
    fmt::print("set-up {:.1f} s CPU; {} steps from step {} ({} phase) in {:.2f} s CPU: {:.3f} ms per step\n", t1 - t0,
               done, first, test->phase_name(), t2 - t1, 1e3 * (t2 - t1) / static_cast<double>(done));
    fmt::print("per step: {:.1f} pair tests, {:.1f} touching pairs, {} broadphase rebuilds in all\n",
               static_cast<double>(p.pair_tests) / done, static_cast<double>(p.contacts) / done, p.broadphase_rebuilds);
    fmt::print("state hash {:016x}\n", state_hash(test->world().state));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_sh_steps: %s\n", e.what());
    return 1;
  }
  return 0;
}
