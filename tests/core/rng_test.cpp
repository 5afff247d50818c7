// The seeded generator: same seed, same numbers; sane distributions.
#include "core/rng.h"

#include <gtest/gtest.h>

using namespace grainlab;

TEST(Rng, SameSeedSameSequenceDifferentSeedDifferent) {
  Rng a(42), b(42), c(43);
  for (int i = 0; i < 1000; ++i) {
    const auto x = a.next_u64();
    EXPECT_EQ(x, b.next_u64());
    EXPECT_NE(x, c.next_u64());
  }
}

TEST(Rng, UniformUnitVectorsAndRotationsAreSane) {
  Rng r(7);
  double sum = 0;
  Vec3 mean = Vec3::Zero();
  const int n = 100000;
  for (int i = 0; i < n; ++i) {
    const double u = r.uniform();
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    sum += u;
    const Vec3 v = r.unit_vector();
    ASSERT_NEAR(v.norm(), 1.0, 1e-12);
    mean += v;
    ASSERT_NEAR(r.rotation().norm(), 1.0, 1e-12);
  }
  EXPECT_NEAR(sum / n, 0.5, 0.01);
  EXPECT_LT((mean / n).norm(), 0.01);
}
