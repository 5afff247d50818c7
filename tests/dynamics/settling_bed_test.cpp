// A bed of convex grains settles to rest in a box; the result does not depend
// on the thread count.
#include "lab/settling_bed.h"
#include "state_compare.h"

#include <gtest/gtest.h>

#include <set>

using namespace grainlab;

namespace {

SettlingBedSpec test_bed() {
  SettlingBedSpec spec;
  spec.grains = 240;
  spec.hull_points = 102;  // 200-face hulls keep the test quick
  spec.seed = 11;
  spec.material.youngs_modulus = 1e7;
  return spec;
}

}  // namespace

TEST(SettlingBed, ConvexGrainsComeToRestInsideTheBox) {
  SettlingBed bed = make_settling_bed(test_bed());
  World& w = bed.world;
  const double dt = 0.2 * w.critical_time_step();
  double worst_overlap = 0;
  double ke_peak = 0, ke = 0;
  // Falls of a few grain sizes take ~0.05 s; rearrangements and the last
  // rattlers need ~0.4 s more.
  const int steps = static_cast<int>(0.5 / dt);
  for (int i = 0; i < steps; ++i) {
    w.step(dt);
    ke = w.kinetic_energy();
    ke_peak = std::max(ke_peak, ke);
    // Impact overlaps grow with stiffness and fall speed (Hertz: delta_max ~
    // v^{4/5}); the promise is about the bed at rest. The last rattlers'
    // landings between 0.2 and 0.4 s reach 0.003-0.011 of the radius,
    // depending on the seed and on rounding (6 seeds, 2026-11-30, before and
    // after the GJK simplex cache alike); after 0.4 s, 0.0019-0.0022.
    if (w.state.time > 0.4) worst_overlap = std::max(worst_overlap, max_relative_overlap(w));
    ASSERT_TRUE(all_grains_inside(bed)) << "a grain left the box at step " << i;
  }
  // At rest the kinetic energy is a tiny fraction of its peak during the fall.
  EXPECT_LT(ke, 1e-4 * ke_peak);
  // Overlaps in the bed below 1 % of the grain radius.
  EXPECT_LT(worst_overlap, 0.01);
  // Every grain rests on something.
  EXPECT_GT(w.contact_count(), w.model.bodies.size());
  // At rest the walls carry the whole weight of the bed.
  double weight = 0, carried = 0;
  for (const BodyModel& b : w.model.bodies) weight += b.gravity_mass * 9.81;
  for (const WallState& ws : w.state.walls) carried -= ws.force.z();
  EXPECT_NEAR(carried / weight, 1.0, 1e-3);
}

// Large enough for every parallel branch of the step: more than 256 grains
// (compute_bounds' parallel reduction, the integrator's chunks of 256) and
// hundreds of candidate and touching pairs (narrowphase chunks of 32, force
// chunks of 128). Each World has its own thread count; none leaks to the next.
TEST(SettlingBed, OneTwoAndThreeThreadsGiveIdenticalStates) {
  SettlingBedSpec spec = test_bed();
  spec.grains = 320;
  spec.hull_points = 38;  // 72-face hulls: the test is about threads, not shapes
  const auto run = [&](int threads) {
    SettlingBed bed = make_settling_bed(spec);
    bed.world.settings.threads = threads;
    bed.world.settings.serial_below = 0;  // every loop in parallel, however few its items
    bed.world.model.gravity *= 20;  // the lattice lands and piles up in few steps
    const double dt = 0.2 * bed.world.critical_time_step();
    const int steps = static_cast<int>(0.03 / dt);
    for (int i = 0; i < steps; ++i) bed.world.step(dt);
    return bed.world;
  };
  const World one = run(1);
  EXPECT_GT(one.model.bodies.size(), 256u);
  EXPECT_GT(one.state.pairs.size(), 256u) << "too few candidate pairs for the parallel narrowphase";
  EXPECT_GT(one.contact_count(), 256u) << "too few touching pairs for the parallel force loop";
  for (int threads : {2, 3}) {
    const World many = run(threads);
    EXPECT_EQ(many.settings.threads, threads);
    EXPECT_TRUE(testing_support::same_state_bits(one.state, many.state)) << "1 and " << threads << " threads differ";
  }
}

// A bed of spheres: on one thread the grain contacts are made inside the
// forces phase a batch at a time (World::step's compact pass), on more in
// two parallel passes over the pairs; the states are the same bit for bit.
TEST(SettlingBed, SpheresOnOneTwoAndThreeThreadsGiveIdenticalStates) {
  SettlingBedSpec spec = test_bed();
  spec.grains = 400;
  spec.spheres = true;
  const auto run = [&](int threads) {
    SettlingBed bed = make_settling_bed(spec);
    bed.world.settings.threads = threads;
    bed.world.settings.serial_below = 0;
    bed.world.model.gravity *= 20;
    const double dt = 0.2 * bed.world.critical_time_step();
    const int steps = static_cast<int>(0.03 / dt);
    for (int i = 0; i < steps; ++i) bed.world.step(dt);
    return bed.world;
  };
  const World one = run(1);
  EXPECT_GT(one.contact_count(), 400u) << "too few contacts to fill many batches and blocks";
  for (int threads : {2, 3}) {
    const World many = run(threads);
    EXPECT_TRUE(testing_support::same_state_bits(one.state, many.state)) << "1 and " << threads << " threads differ";
  }
}

// threads = 0 leaves the count to the step's tuner (core/thread_tuner.h).
// Here its windows are one step long and it holds nothing, so the count
// changes every few steps: the state is still bit for bit the 1-thread one.
TEST(SettlingBed, ThreadsChosenByTimingChangeNothingButTheSpeed) {
  SettlingBedSpec spec = test_bed();
  spec.grains = 320;
  spec.hull_points = 38;
  const auto run = [&](int threads, std::set<int>* used) {
    SettlingBed bed = make_settling_bed(spec);
    World& w = bed.world;
    w.settings.threads = threads;
    w.settings.serial_below = 0;
    w.settings.thread_tuning.min_seconds = 0;
    w.settings.thread_tuning.min_steps = 1;
    w.settings.thread_tuning.hold_seconds = 0;
    w.model.gravity *= 20;
    const double dt = 0.2 * w.critical_time_step();
    const int steps = static_cast<int>(0.03 / dt);
    for (int i = 0; i < steps; ++i) {
      w.step(dt);
      if (used) used->insert(w.step_threads());
    }
    return bed.world;
  };
  const World one = run(1, nullptr);
  std::set<int> used;
  const World tuned = run(0, &used);
  ASSERT_GE(tuned.thread_tuner().max_threads(), 2) << "ctest runs the tests with OMP_NUM_THREADS=2";
  EXPECT_GT(tuned.thread_tuner().trials(), 10);
  EXPECT_EQ(used, (std::set<int>{1, 2}));
  EXPECT_TRUE(testing_support::same_state_bits(one.state, tuned.state));
}
