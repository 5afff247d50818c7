// Coordination number and per-grain contact counts on hand-built contacts and
// on a small resting column built through the World API.
#include "analysis/coordination.h"
#include "dynamics/world.h"

#include <gtest/gtest.h>

using namespace grainlab;
using namespace grainlab::analysis;

namespace {

Contact pair(Index a, Index b, bool touching) {
  Contact pc;
  pc.a = a;
  pc.b = b;
  pc.geo.touching = touching;
  return pc;
}

// Five grains: contacts 0-1, 1-2, 2-3; 3-4 is a candidate pair not touching;
// grain 0 touches wall 0, grain 4 is near wall 1 without touching it.
State chain() {
  State s;
  s.bodies.resize(5);
  s.contacts = {pair(0, 1, true), pair(1, 2, true), pair(2, 3, true), pair(3, 4, false)};
  s.wall_contacts = {pair(0, 0, true), pair(1, 4, false)};
  return s;
}

}  // namespace

TEST(Coordination, CountsAndCoordinationOfAHandBuiltChain) {
  const State s = chain();
  EXPECT_EQ(contact_counts(s), (std::vector<Index>{1, 2, 2, 1, 0}));
  EXPECT_EQ(contact_counts(s, true), (std::vector<Index>{2, 2, 2, 1, 0}));
  // Eq. 22: 2 N_c / N_p = 2 x 3 / 5.
  EXPECT_DOUBLE_EQ(coordination_number(s), 6.0 / 5.0);
  // Subsets: per-grain mean of the grain-grain contact counts.
  const GrainMask middle = {0, 1, 1, 0, 0};
  EXPECT_DOUBLE_EQ(coordination_number(s, &middle), 2.0);
  const GrainMask ends = {1, 0, 0, 0, 1};
  EXPECT_DOUBLE_EQ(coordination_number(s, &ends), 0.5);
  const GrainMask all(5, 1);
  EXPECT_DOUBLE_EQ(coordination_number(s, &all), coordination_number(s));
  const GrainMask none(5, 0);
  EXPECT_EQ(coordination_number(s, &none), 0.0);
  const GrainMask wrong(4, 1);
  EXPECT_THROW(coordination_number(s, &wrong), std::invalid_argument);
}

TEST(Coordination, RestingColumnAgreesWithTheWorldsContactCount) {
  // Three spheres stacked on a floor, each pressed 1 um into the one below.
  World w;
  w.model.gravity = Vec3::Zero();
  Material m;
  m.youngs_modulus = 1e7;
  const Index mat = w.model.add_material(m);
  const Index sphere = w.model.add_sphere_shape(1e-3);
  const double r = 1e-3, d = 1e-6;
  for (int k = 0; k < 3; ++k) w.add_body(sphere, mat, 1.0, Vec3(0, 0, r - d + k * (2 * r - d)));
  w.add_body(sphere, mat, 1.0, Vec3(0.01, 0, 0.01));  // a floating grain, in no contact
  w.add_plane(Vec3::Zero(), Vec3::UnitZ(), mat, "floor");
  w.step(1e-3 * w.critical_time_step());
  ASSERT_EQ(w.contact_count(), 3u);  // two grain-grain, one with the floor
  EXPECT_EQ(contact_counts(w.state), (std::vector<Index>{1, 2, 1, 0}));
  EXPECT_DOUBLE_EQ(coordination_number(w.state), 2.0 * 2 / 4);
  std::size_t with_walls = 0;
  for (Index c : contact_counts(w.state, true)) with_walls += static_cast<std::size_t>(c);
  // Each grain-grain contact counts for two grains, a wall contact for one.
  EXPECT_EQ(with_walls, 2u * 2 + 1);
}
