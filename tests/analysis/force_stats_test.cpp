// Normal contact force statistics and the strong contacts, on hand-built contacts.
#include "analysis/force_stats.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace grainlab;
using namespace grainlab::analysis;

namespace {

Contact pair(Index a, Index b, bool touching, double f_n) {
  Contact pc;
  pc.a = a;
  pc.b = b;
  pc.geo.touching = touching;
  pc.normal_force = f_n;
  return pc;
}

}  // namespace

TEST(ForceStats, MeanMaxSpreadAndStrongContacts) {
  State s;
  s.bodies.resize(6);
  // Four contacts of 1, 2, 3 and 6 N; a pair no longer touching still holds a
  // stale 100 N, and a wall contact 50 N: neither counts.
  s.contacts = {pair(0, 1, true, 1), pair(0, 2, false, 100), pair(1, 2, true, 2), pair(2, 3, true, 6),
             pair(3, 4, true, 3)};
  s.wall_contacts = {pair(0, 5, true, 50)};
  const ForceStats st = force_stats(s);
  EXPECT_EQ(st.contacts, 4u);
  EXPECT_DOUBLE_EQ(st.mean, 3.0);
  EXPECT_DOUBLE_EQ(st.max, 6.0);
  // Population deviation: sqrt((4 + 1 + 9 + 0) / 4).
  EXPECT_DOUBLE_EQ(st.std_dev, std::sqrt(3.5));
  // Strong: above the mean, strictly (3 N is not).
  EXPECT_EQ(st.strong, (std::vector<Index>{3}));
  EXPECT_DOUBLE_EQ(st.strong_fraction, 0.25);
}

TEST(ForceStats, NoContactsGiveZeros) {
  State s;
  s.bodies.resize(2);
  s.contacts = {pair(0, 1, false, 5)};
  const ForceStats st = force_stats(s);
  EXPECT_EQ(st.contacts, 0u);
  EXPECT_EQ(st.mean, 0.0);
  EXPECT_EQ(st.max, 0.0);
  EXPECT_EQ(st.strong_fraction, 0.0);
  EXPECT_TRUE(st.strong.empty());
}
