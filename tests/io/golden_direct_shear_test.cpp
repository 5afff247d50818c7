// Golden regression: a tiny direct shear (tests/lab/tiny_box.h, sheared to
// 1.5 % strain) must reproduce, byte for byte, the series.csv stored in
// tests/data/golden/ (protocol columns and the analysis columns of
// io/shear_analysis.h) and a hash of its final state (every grain's position,
// velocity, angular velocity and orientation, every wall's position, velocity
// and force, and the tangential spring of every touching contact, as IEEE
// bits). It guards refactors: a change that moves any bit of the physics,
// the protocol or the analysis fails here.
//
// A change that must alter the bits says why in its commit and re-blesses once:
//   GRAINLAB_BLESS=1 build/test_io --gtest_filter='Golden*'
// rewrites tests/data/golden/ (then commit the new files with the reason).
#include "core/parallel.h"
#include "io/shear_analysis.h"
#include "io/table.h"
#include "lab/direct_shear.h"
#include "lab/tiny_box.h"
#include "file_text.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

using namespace grainlab;

namespace {

namespace fs = std::filesystem;

const fs::path kGoldenDir = fs::path(GRAINLAB_TEST_DATA) / "golden";

// FNV-1a 64 over the IEEE bits of doubles and the bytes of integers, in a
// fixed order: independent of struct layout, so a refactor that only moves
// fields keeps the hash.
struct BitHash {
  std::uint64_t h = 1469598103934665603ull;
  void byte(std::uint8_t b) { h = (h ^ b) * 1099511628211ull; }
  void u64(std::uint64_t v) {
    for (int i = 0; i < 8; ++i) byte(static_cast<std::uint8_t>(v >> (8 * i)));
  }
  void f64(double v) { u64(std::bit_cast<std::uint64_t>(v)); }
  void vec(const Vec3& v) { f64(v.x()), f64(v.y()), f64(v.z()); }
};

// The final state's physics, hashed: bodies, walls, and the springs of the
// touching contacts ordered by (grain pair before wall pair, a, b).
std::uint64_t physics_hash(const State& s) {
  BitHash h;
  h.f64(s.time);
  h.u64(static_cast<std::uint64_t>(s.step));
  for (const BodyState& b : s.bodies) {
    h.vec(b.x), h.vec(b.v), h.vec(b.w);
    h.f64(b.q.x()), h.f64(b.q.y()), h.f64(b.q.z()), h.f64(b.q.w());
  }
  for (const WallState& w : s.walls) h.vec(w.x), h.vec(w.v), h.vec(w.force);
  std::vector<std::tuple<int, Index, Index, Vec3>> springs;
  for (const Contact& pc : s.contacts)
    if (in_contact(pc)) springs.emplace_back(0, pc.a, pc.b, pc.xi);
  for (const Contact& pc : s.wall_contacts)
    if (in_contact(pc)) springs.emplace_back(1, pc.a, pc.b, pc.xi);
  std::sort(springs.begin(), springs.end(), [](const auto& l, const auto& r) {
    return std::tie(std::get<0>(l), std::get<1>(l), std::get<2>(l)) <
           std::tie(std::get<0>(r), std::get<1>(r), std::get<2>(r));
  });
  h.u64(springs.size());
  for (const auto& [kind, a, b, xi] : springs) {
    h.u64(static_cast<std::uint64_t>(kind));
    h.u64(static_cast<std::uint64_t>(a)), h.u64(static_cast<std::uint64_t>(b));
    h.vec(xi);
  }
  return h.h;
}

void write_text(const fs::path& p, const std::string& text) {
  fs::create_directories(p.parent_path());
  std::ofstream(p, std::ios::binary) << text;
}

TEST(GoldenDirectShear, ReproducesSeriesAndFinalStateBitForBit) {
  LabSpec spec = testing_support::tiny_box_spec();
  spec.settings<ShearSpec>().final_strain = 0.015;
  DirectShearTest test(spec);
  observe_shear_analysis(test);
  while (test.advance(1000)) {
  }
  ASSERT_EQ(test.phase(), ShearPhase::Done);

  Table t;
  t.columns = test.series_columns();
  t.rows = test.series();
  const std::string csv = t.to_csv();
  const std::string hash = fmt::format("{:016x}\n", physics_hash(test.world().state));
  std::printf("golden: %zu rows, %lld steps, final state hash %s", t.rows.size(),
              static_cast<long long>(test.world().state.step), hash.c_str());

  if (std::getenv("GRAINLAB_BLESS")) {
    write_text(kGoldenDir / "direct_shear_series.csv", csv);
    write_text(kGoldenDir / "direct_shear_state_hash.txt", hash);
    GTEST_SKIP() << "blessed: rewrote " << kGoldenDir.string();
  }
  ASSERT_TRUE(fs::exists(kGoldenDir / "direct_shear_series.csv"))
      << "no golden files: run once with GRAINLAB_BLESS=1";
  const std::string golden_csv = test::file_text(kGoldenDir / "direct_shear_series.csv");
  EXPECT_EQ(csv.size(), golden_csv.size());
  EXPECT_TRUE(csv == golden_csv) << "series.csv differs from " << (kGoldenDir / "direct_shear_series.csv").string();
  EXPECT_EQ(hash, test::file_text(kGoldenDir / "direct_shear_state_hash.txt"));
}

}  // namespace
