// Where the narrowphase time goes on the settled bed of bench_scenes: each
// grain-grain candidate pair of one step is sorted by the path it takes and
// timed on its own (its cache copied, the call repeated), so a change to one
// path shows in that path's figure. Not a test: it prints figures.
//
//   build/bench_pair_paths [--grains N] [--settle STEPS] [--repeat K]
//
// Paths: bounding spheres apart (no narrowphase); apart along the last normal
// by more than 1 % of the size (no GJK); touching; anything else (near but
// apart, or a cold pair: GJK/EPA). Times are per call, one thread.
#include "bench_args.h"
#include "collision/dispatch.h"
#include "core/timer.h"
#include "core/wait_policy.h"
#include "lab/settling_bed.h"

#include <fmt/format.h>

#include <array>
#include <cstring>
#include <string>

using namespace grainlab;

namespace {

enum Path { kSpheresApart, kFarApart, kTouching, kOther, kPathCount };
constexpr std::array<const char*, kPathCount> kPathNames = {
    "bounding spheres apart", "apart along last normal", "touching", "near apart or cold (GJK/EPA)"};

}  // namespace

int main(int argc, char** argv) {
  grainlab::bench::check_args(argc, argv, "[--grains N] [--settle STEPS] [--repeat K]",
                              {"--grains", "--settle", "--repeat"});
  grainlab::use_passive_wait_by_default(argv);
  int grains = 2000, settle = 6000, repeat = 20;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--grains")) grains = std::stoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--settle")) settle = std::stoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--repeat")) repeat = std::stoi(argv[i + 1]);
  }
  SettlingBedSpec spec;
  spec.grains = grains;
  SettlingBed bed = make_settling_bed(spec);
  World& w = bed.world;
  const double dt = 0.2 * w.critical_time_step();
  for (int i = 0; i < settle; ++i) w.step(dt);
  fmt::print("settled bed of {} grains with ~2000-face hulls after {} steps: {:.2f} contacts per grain\n",
             w.model.bodies.size(), settle, 2.0 * w.contact_count() / w.model.bodies.size());

  std::array<long, kPathCount> count{};
  std::array<double, kPathCount> seconds{};
  for (const CandidatePair& pair : w.state.pairs) {
    const double reach = w.model.bodies[pair.a].bounding_radius + w.model.bodies[pair.b].bounding_radius;
    if ((w.state.bodies[pair.b].x - w.state.bodies[pair.a].x).squaredNorm() > reach * reach) {
      ++count[kSpheresApart];
      continue;
    }
    const PosedShape a = w.posed_body(pair.a), b = w.posed_body(pair.b);
    SubContact out[kMaxSubContacts];
    PairCache probe = pair.cache;
    const int n = collide_shapes(a, b, probe, out);
    Path path = kOther;
    if (n > 0 && out[0].geo.touching) path = kTouching;
    else if (pair.cache.warm && n > 0 && out[0].geo.point == Vec3::Zero()) path = kFarApart;  // no GJK ran
    Stopwatch clock;
    for (int k = 0; k < repeat; ++k) {
      PairCache c = pair.cache;
      collide_shapes(a, b, c, out);
    }
    ++count[path];
    seconds[path] += clock.seconds() / repeat;
  }
  double total = 0;
  for (const double s : seconds) total += s;
  fmt::print("{:<30} {:>7} {:>12} {:>10}\n", "path", "pairs", "us per pair", "ms total");
  for (int p = 0; p < kPathCount; ++p)
    fmt::print("{:<30} {:>7} {:>12.2f} {:>10.3f}\n", kPathNames[p], count[p],
               count[p] ? 1e6 * seconds[p] / count[p] : 0.0, 1e3 * seconds[p]);
  fmt::print("narrowphase of one step on one thread, timed pair by pair: {:.2f} ms\n", 1e3 * total);
  return 0;
}
