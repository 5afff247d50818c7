// index_densities.json (io/preparation_files.h): a finished file gives its
// e_min and e_max to a run with the same inputs; an unfinished one gives the
// preparations it holds, bit for bit, and never its (absent) means.
#include "io/preparation_files.h"
#include "io_test_helpers.h"

#include <gtest/gtest.h>

using namespace grainlab;

namespace {

IndexPreparation preparation(std::uint64_t seed, double friction, double e) {
  IndexPreparation p;
  p.seed = seed;
  p.friction = friction;
  p.void_ratio = e;
  p.whole_void_ratio = e + 0.1234567890123;
  p.settled = seed % 2 == 0;
  p.steps = 123456789012 + seed;
  p.wall_s = 1e3 / 7;
  return p;
}

}  // namespace

TEST(IndexDensitiesFile, AnUnfinishedFileGivesItsPreparationsAndNoMeans) {
  test::IoTempDir dir;
  const auto file = dir.path / "index_densities.json";
  LabSpec spec;
  EXPECT_FALSE(cached_index_densities(file, spec));  // no file
  EXPECT_TRUE(unfinished_index_densities(file, spec).dense.empty());

  IndexDensities partial;
  partial.dense = {preparation(7, 0, 0.1 / 3), preparation(8, 0, 2.0 / 3)};
  write_index_densities(file, spec, partial, false);
  EXPECT_FALSE(cached_index_densities(file, spec));
  const IndexDensities back = unfinished_index_densities(file, spec);
  ASSERT_EQ(back.dense.size(), 2u);
  EXPECT_TRUE(back.loose.empty());
  for (std::size_t i = 0; i < 2; ++i) {
    const IndexPreparation &a = partial.dense[i], &b = back.dense[i];
    EXPECT_EQ(a.seed, b.seed);
    EXPECT_EQ(a.friction, b.friction);
    EXPECT_EQ(a.void_ratio, b.void_ratio);
    EXPECT_EQ(a.whole_void_ratio, b.whole_void_ratio);
    EXPECT_EQ(a.settled, b.settled);
    EXPECT_EQ(a.steps, b.steps);
    EXPECT_EQ(a.wall_s, b.wall_s);
  }
  // Other inputs (here the seed) take nothing from it.
  LabSpec other = spec;
  other.seed += 1;
  EXPECT_TRUE(unfinished_index_densities(file, other).dense.empty());

  IndexDensities finished = partial;
  finished.loose = {preparation(7, 1, 0.75)};
  finished.e_min = 0.5;
  finished.e_max = 0.75;
  write_index_densities(file, spec, finished);
  const auto cached = cached_index_densities(file, spec);
  ASSERT_TRUE(cached);
  EXPECT_EQ(cached->first, 0.5);
  EXPECT_EQ(cached->second, 0.75);
  EXPECT_TRUE(unfinished_index_densities(file, spec).dense.empty());
  EXPECT_FALSE(cached_index_densities(file, other));
}
