// Collision layer benchmarks: support queries, GJK/EPA on shallow-overlapping
// 1000-vertex hull pairs (warm and cold), sweep and prune.
#include "../tests/collision/test_shapes.h"
#include "collision/broadphase.h"
#include "collision/gjk.h"
#include "collision/narrowphase.h"

#include <benchmark/benchmark.h>

namespace grainlab {
namespace {

constexpr double kSize = 1e-3;  // grain size (m)

struct PairScene {
  std::vector<testing::TestHull> hulls;
  std::vector<std::pair<PolytopeShape, PolytopeShape>> pairs;
  std::vector<Vec3> dirs;
};

// Pairs of ~1000-vertex hulls overlapping by 1e-4..1e-2 of their size (or
// separated by that much), at positions ~1e-2 m.
const PairScene& scene(bool blob, bool overlapping) {
  static PairScene s[2][2];
  PairScene& sc = s[blob][overlapping];
  if (!sc.pairs.empty()) return sc;
  Rng rng(blob ? 7 : 8);
  for (int i = 0; i < 8; ++i)
    sc.hulls.push_back(blob ? testing::random_blob_hull(rng, 20000)
                            : testing::random_ellipsoid_hull(rng, 1000, 0.7, 1.3));
  while (sc.pairs.size() < 256) {
    const auto& ha = sc.hulls[sc.pairs.size() % 8];
    const auto& hb = sc.hulls[(sc.pairs.size() + 3) % 8];
    PolytopeShape a{&ha.poly, rng.rotation().toRotationMatrix(), rng.unit_vector() * 1e-2, kSize, 0};
    PolytopeShape b{&hb.poly, rng.rotation().toRotationMatrix(), a.pos, kSize, 0};
    const Vec3 u = rng.unit_vector();
    const double along = u.dot(a.support(u) - b.support(-u));  // h_C(u) with B at A
    const double delta = rng.uniform(1e-4, 1e-2) * kSize;
    b.pos = a.pos + (along - (overlapping ? delta : -delta)) * u;
    Vec3 dir = u;
    const ContactResult r = gjk_epa(a, b, dir);
    if (r.touching != overlapping) continue;
    sc.pairs.emplace_back(a, b);
    sc.dirs.push_back(dir);
  }
  return sc;
}

void BM_SupportWarm(benchmark::State& st) {
  const PairScene& sc = scene(false, true);
  PolytopeShape a = sc.pairs[0].first;
  Rng rng(1);
  std::vector<Vec3> dirs;
  Vec3 d = rng.unit_vector();
  for (int i = 0; i < 1024; ++i) dirs.push_back(d = (d + 0.05 * rng.unit_vector()).normalized());
  std::size_t i = 0;
  for (auto _ : st) benchmark::DoNotOptimize(a.support(dirs[i++ & 1023]));
  st.counters["vertices"] = static_cast<double>(a.poly->size());
}
BENCHMARK(BM_SupportWarm);

void BM_SupportCold(benchmark::State& st) {
  const PairScene& sc = scene(false, true);
  PolytopeShape a = sc.pairs[0].first;
  Rng rng(2);
  std::vector<Vec3> dirs;
  for (int i = 0; i < 1024; ++i) dirs.push_back(rng.unit_vector());
  std::size_t i = 0;
  for (auto _ : st) benchmark::DoNotOptimize(a.support(dirs[i++ & 1023]));
}
BENCHMARK(BM_SupportCold);

// arg0: 0 ellipsoid hulls, 1 irregular hulls; arg1: 1 warm (cached dir and hints), 0 cold.
void BM_GjkEpaOverlap(benchmark::State& st) {
  const bool blob = st.range(0) != 0, warm = st.range(1) != 0;
  const PairScene& sc = scene(blob, true);
  auto pairs = sc.pairs;
  auto dirs = sc.dirs;
  std::size_t i = 0;
  double gjk_its = 0, epa_its = 0, unconverged = 0;
  for (auto _ : st) {
    const std::size_t k = i++ % pairs.size();
    auto& [a, b] = pairs[k];
    Vec3 dir = dirs[k];
    if (!warm) {
      a.hint = b.hint = 0;
      dir = b.pos - a.pos;
    }
    GjkEpaInfo info;
    benchmark::DoNotOptimize(gjk_epa(a, b, dir, &info));
    gjk_its += info.gjk_iterations;
    epa_its += info.epa_iterations;
    unconverged += !info.epa_converged;
    if (warm) dirs[k] = dir;
  }
  const double calls = static_cast<double>(i);
  st.counters["vertices"] = static_cast<double>(pairs[0].first.poly->size());
  st.counters["gjk_it"] = gjk_its / calls;
  st.counters["epa_it"] = epa_its / calls;
  st.counters["unconv"] = unconverged / calls;
}
BENCHMARK(BM_GjkEpaOverlap)->Args({0, 1})->Args({0, 0})->Args({1, 1})->Args({1, 0});

// The narrowphase's real path for touching polytope pairs: warm translated GJK
// (penetration.h) with EPA as fallback, through collide_convex.
void BM_CollideConvexWarm(benchmark::State& st) {
  const PairScene& sc = scene(st.range(0) != 0, true);
  auto pairs = sc.pairs;
  auto dirs = sc.dirs;
  std::size_t i = 0;
  for (auto _ : st) {
    const std::size_t k = i++ % pairs.size();
    auto& [a, b] = pairs[k];
    benchmark::DoNotOptimize(collide_convex(a, b, dirs[k], true));
  }
}
BENCHMARK(BM_CollideConvexWarm)->Arg(0)->Arg(1);

void BM_GjkSeparated(benchmark::State& st) {
  const bool warm = st.range(0) != 0;
  const PairScene& sc = scene(false, false);
  auto pairs = sc.pairs;
  auto dirs = sc.dirs;
  std::size_t i = 0;
  for (auto _ : st) {
    const std::size_t k = i++ % pairs.size();
    auto& [a, b] = pairs[k];
    Vec3 dir = dirs[k];
    if (!warm) {
      a.hint = b.hint = 0;
      dir = b.pos - a.pos;
    }
    benchmark::DoNotOptimize(gjk_epa(a, b, dir));
    if (warm) dirs[k] = dir;
  }
}
BENCHMARK(BM_GjkSeparated)->Arg(1)->Arg(0);

// Boxes of ~one grain size in a cube at packing density; each step moves them
// by ~1e-3 of their size (a DEM step) and finds the pairs.
void BM_SweepAndPrune(benchmark::State& st) {
  const int n = static_cast<int>(st.range(0));
  Rng rng(3);
  const double side = std::cbrt(static_cast<double>(n)) * kSize;
  std::vector<Vec3> pos(n);
  std::vector<Aabb> boxes(n);
  for (auto& p : pos) p = Vec3(rng.uniform(), rng.uniform(), rng.uniform()) * side;
  SweepAndPrune sap;
  std::vector<BodyPair> pairs;
  for (auto _ : st) {
    st.PauseTiming();
    for (int i = 0; i < n; ++i) {
      pos[i] += 1e-3 * kSize * rng.unit_vector();
      boxes[i] = Aabb{pos[i], pos[i]}.inflated(0.5 * kSize);
    }
    st.ResumeTiming();
    sap.find_pairs(boxes, pairs);
    benchmark::DoNotOptimize(pairs.data());
  }
  st.counters["pairs"] = static_cast<double>(pairs.size());
}
BENCHMARK(BM_SweepAndPrune)->Arg(2000)->Arg(20000)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace grainlab

BENCHMARK_MAIN();
