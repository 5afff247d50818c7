// merge_over_split_regions on shapes whose distance maps are known.
#include "ct/neck_merge.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace grainlab::ct {
namespace {

constexpr std::int64_t kN = 40;
const Size3 kSize{kN, kN, kN};

struct Field {
  std::vector<std::uint32_t> labels = std::vector<std::uint32_t>(kN * kN * kN, 0);
  std::vector<float> distance = std::vector<float>(kN * kN * kN, 0.0f);
};

// Labels 1 (x < centre) and 2 (x >= centre) where `depth` (distance to the surface, voxels) is positive.
template <typename Depth>
Field halves(Depth depth) {
  Field f;
  for (std::int64_t k = 0; k < kN; ++k) {
    for (std::int64_t j = 0; j < kN; ++j) {
      for (std::int64_t i = 0; i < kN; ++i) {
        const double x = i - 19.5, y = j - 19.5, z = k - 19.5;
        const double d = depth(x, y, z);
        if (d <= 0) continue;
        const std::size_t v = static_cast<std::size_t>(i + kN * (j + kN * k));
        f.labels[v] = x < 0 ? 1 : 2;
        f.distance[v] = static_cast<float>(d);
      }
    }
  }
  return f;
}

// A capsule (radius 6, axis along x from -8 to 8) cut across its middle: the
// boundary crosses the full section, its saddle is the radius: one grain.
TEST(CtNeckMerge, ABoundaryAcrossAGrainsFullSectionIsMerged) {
  Field f = halves([](double x, double y, double z) {
    const double ax = std::max(0.0, std::abs(x) - 8);
    return 6 - std::sqrt(ax * ax + y * y + z * z);
  });
  EXPECT_EQ(merge_over_split_regions(f.labels, kSize, f.distance, 0.8), 1);
  for (std::uint32_t l : f.labels) EXPECT_TRUE(l == 0 || l == f.labels[19 + kN * (19 + kN * 19)]);
}

// Two balls of radius 8, centres 15 apart, pressed 1 voxel together: the neck's
// saddle (the voxels at x = -0.5 and 0.5) is 8 - 7.5 = 0.5 ... 1 voxel of their 8: two grains.
TEST(CtNeckMerge, ANarrowNeckBetweenTwoBallsIsKept) {
  const auto two_balls = [](double x, double y, double z) {
    return 8 - std::min(std::sqrt((x + 7.5) * (x + 7.5) + y * y + z * z),
                        std::sqrt((x - 7.5) * (x - 7.5) + y * y + z * z));
  };
  Field f = halves(two_balls);
  EXPECT_EQ(merge_over_split_regions(f.labels, kSize, f.distance, 0.3), 0);
  EXPECT_EQ(std::count(f.labels.begin(), f.labels.end(), 1u), std::count(f.labels.begin(), f.labels.end(), 2u));
  // A ratio below the neck's (1/8 here) merges them: the ratio is what decides.
  Field g = halves(two_balls);
  EXPECT_EQ(merge_over_split_regions(g.labels, kSize, g.distance, 0.1), 1);
}

}  // namespace
}  // namespace grainlab::ct
