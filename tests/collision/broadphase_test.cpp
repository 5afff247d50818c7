// Sweep and prune against the O(n^2) reference on random boxes.
#include "collision/broadphase.h"
#include "core/rng.h"

#include <gtest/gtest.h>

namespace grainlab {
namespace {

std::vector<Aabb> random_boxes(Rng& rng, int n, double side, double size) {
  std::vector<Aabb> boxes(n);
  for (auto& b : boxes) {
    const Vec3 c(rng.uniform(0, side), rng.uniform(0, side * 0.3), rng.uniform(0, side * 0.6));
    const Vec3 h(rng.uniform(0.2, 1) * size, rng.uniform(0.2, 1) * size, rng.uniform(0.2, 1) * size);
    b = Aabb{c - h, c + h};
  }
  return boxes;
}

TEST(SweepAndPrune, MatchesBruteForceOverMovesAndCountChanges) {
  Rng rng(31);
  std::size_t total_pairs = 0;
  for (const double density : {0.2, 1.0, 3.0}) {
    SweepAndPrune sap;
    std::vector<BodyPair> got, want;
    int n = 300;
    auto boxes = random_boxes(rng, n, 20, density);
    for (int step = 0; step < 40; ++step) {
      // Small random moves; occasionally a big reshuffle or a change of count.
      for (auto& b : boxes) {
        const Vec3 d = 0.05 * density * rng.unit_vector();
        b.lo += d, b.hi += d;
      }
      if (step % 10 == 5) {
        n = static_cast<int>(rng.uniform(50, 500));
        const auto extra = random_boxes(rng, n, 20, density);
        boxes.resize(n);
        for (int i = 0; i < n; ++i)
          if (rng.uniform() < 0.3) boxes[i] = extra[i];
        if (n > 0) boxes[rng.uniform() < 0.5 ? 0 : n - 1] = boxes[n / 2];  // exact duplicates
      }
      if (step == 20) {  // stretch along another axis: the sweep axis changes
        for (auto& b : boxes) {
          b.lo.y() *= 5, b.hi.y() *= 5;
        }
      }
      sap.find_pairs(boxes, got);
      brute_force_pairs(boxes, want);
      ASSERT_EQ(got, want) << "density " << density << " step " << step;
      total_pairs += want.size();
    }
  }
  EXPECT_GT(total_pairs, 1000u);
}

TEST(SweepAndPrune, TouchingBoxesAndSmallCounts) {
  SweepAndPrune sap;
  std::vector<BodyPair> got, want;
  std::vector<Aabb> boxes;
  sap.find_pairs(boxes, got);
  EXPECT_TRUE(got.empty());
  boxes.push_back({Vec3(0, 0, 0), Vec3(1, 1, 1)});
  sap.find_pairs(boxes, got);
  EXPECT_TRUE(got.empty());
  boxes.push_back({Vec3(1, 0, 0), Vec3(2, 1, 1)});  // shares a face: overlaps (closed boxes)
  boxes.push_back({Vec3(2, 1, 1), Vec3(3, 2, 2)});  // shares a corner with box 1
  boxes.push_back({Vec3(0, 0, 1.5), Vec3(3, 3, 3)});
  sap.find_pairs(boxes, got);
  brute_force_pairs(boxes, want);
  EXPECT_EQ(got, want);
  EXPECT_EQ(want, (std::vector<BodyPair>{{0, 1}, {1, 2}, {2, 3}}));
}

TEST(SweepAndPrune, OutputSortedAndDeterministic) {
  Rng rng(32);
  const auto boxes = random_boxes(rng, 2000, 30, 1.0);
  SweepAndPrune a, b;
  std::vector<BodyPair> pa, pb;
  a.find_pairs(boxes, pa);
  // b sees a different history first.
  b.find_pairs(random_boxes(rng, 2000, 30, 1.0), pb);
  b.find_pairs(boxes, pb);
  EXPECT_EQ(pa, pb);
  EXPECT_TRUE(std::is_sorted(pa.begin(), pa.end()));
  for (const auto& [i, j] : pa) EXPECT_LT(i, j);
}

}  // namespace
}  // namespace grainlab
