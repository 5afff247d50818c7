// The step's thread count chosen by timing (core/thread_tuner.h), fed with
// step times from a cost model instead of a clock.
#include "core/thread_tuner.h"

#include <gtest/gtest.h>

#include <functional>
#include <vector>

using namespace grainlab;

namespace {

// Runs `steps` steps whose time is cost(threads, step index).
void run(ThreadTuner& t, int steps, const std::function<double(int, int)>& cost, int first = 0) {
  for (int i = first; i < first + steps; ++i) t.record(cost(t.threads(), i));
}

ThreadTuning windows_of(int steps, double hold_seconds = 30, double drift = 1.3) {
  ThreadTuning timing;
  timing.min_seconds = 0;
  timing.min_steps = steps;
  timing.hold_seconds = hold_seconds;
  timing.drift = drift;
  return timing;
}

}  // namespace

TEST(ThreadTuner, KeepsTheCountWhoseStepsAreFastest) {
  ThreadTuner cheap_world(2, windows_of(10));
  run(cheap_world, 40, [](int n, int) { return n == 1 ? 1e-3 : 1.4e-3; });  // the 2000-bead lab
  EXPECT_EQ(cheap_world.trials(), 1);
  EXPECT_EQ(cheap_world.chosen(), 1);
  EXPECT_EQ(cheap_world.threads(), 1);

  ThreadTuner faceted(2, windows_of(10));
  run(faceted, 40, [](int n, int) { return n == 1 ? 8e-3 : 5e-3; });
  EXPECT_EQ(faceted.chosen(), 2);
  EXPECT_EQ(faceted.threads(), 2);

  // Candidates 8, 4, 2, 1 with a cost that falls with the threads' share of
  // the work and grows with their hand-over: least at 4.
  ThreadTuner many(8, windows_of(10));
  run(many, 80, [](int n, int) { return 1.0 / n + 0.1 * n; });
  EXPECT_EQ(many.trials(), 1);
  EXPECT_EQ(many.chosen(), 4);
}

TEST(ThreadTuner, EveryCandidateIsTriedForWholeWindowsBeforeAChoice) {
  ThreadTuning timing;
  timing.min_steps = 3;
  timing.min_seconds = 0.5;  // 5 steps of 0.1 s: both conditions hold from the 5th
  ThreadTuner t(2, timing);
  std::vector<int> used;
  for (int i = 0; i < 20; ++i) {
    used.push_back(t.threads());
    t.record(0.1);
  }
  const std::vector<int> expected = {2, 2, 2, 2, 2, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 2, 2, 2, 2, 2};
  EXPECT_EQ(used, expected);
  EXPECT_EQ(t.trials(), 1);
  EXPECT_EQ(t.chosen(), 2) << "a tie goes to the count tried first";
}

// A step cost rising steadily through the trial (a packing densifying) must
// not favour the count tried first: the windows run 2, 1, 1, 2, so a linear
// drift weighs on both alike and a 1 % advantage still decides.
TEST(ThreadTuner, ASteadyDriftDuringTheTrialFavoursNoCount) {
  for (const double advantage_of_one : {0.99, 1.01}) {
    ThreadTuner t(2, windows_of(10));
    run(t, 40, [&](int n, int i) { return (1.0 + 0.05 * i) * (n == 1 ? advantage_of_one : 1.0); });
    EXPECT_EQ(t.chosen(), advantage_of_one < 1 ? 1 : 2) << advantage_of_one;
  }
}

// The machine's load and the step's cost change during a run: after holding
// its choice for hold_seconds of step time the tuner tries again, even when
// the held count's steps kept their time.
TEST(ThreadTuner, TriesAgainAfterItsHoldAndFollowsAChange) {
  ThreadTuner t(2, windows_of(10, 1.0, 1e9));
  run(t, 40, [](int n, int) { return n == 1 ? 1e-3 : 2e-3; });
  ASSERT_EQ(t.chosen(), 1);
  // Now two threads win (another process left the machine; shear began).
  const auto later = [](int n, int) { return n == 1 ? 2e-3 : 1e-3; };
  run(t, 400, later);  // 0.8 s of 1-thread steps: still holding
  EXPECT_EQ(t.trials(), 1);
  EXPECT_EQ(t.threads(), 1);
  run(t, 200, later);
  EXPECT_EQ(t.trials(), 2);
  EXPECT_EQ(t.chosen(), 2);
}

TEST(ThreadTuner, OneThreadHasNothingToTry) {
  ThreadTuner t(1, windows_of(1, 0));
  run(t, 100, [](int, int) { return 1.0; });
  EXPECT_EQ(t.threads(), 1);
  EXPECT_EQ(t.trials(), 0);
  EXPECT_EQ(ThreadTuner(0).max_threads(), 1);
}

// When the held count's steps become `drift` times slower (grains landing in
// a deposition, another process taking a core) the tuner tries again at the
// end of that window; noise within the drift does not make it try.
TEST(ThreadTuner, AStepCostThatChangesStartsATrialAtOnce) {
  ThreadTuner t(2, windows_of(10));
  run(t, 40, [](int n, int) { return n == 1 ? 1e-3 : 1.5e-3; });
  ASSERT_EQ(t.chosen(), 1);
  run(t, 1000, [](int n, int i) { return (n == 1 ? 1e-3 : 1.5e-3) * (i % 2 ? 1.1 : 0.9); }, 40);
  EXPECT_EQ(t.trials(), 1) << "10 % noise is not a change";
  // The landed grains: each step is 3 times the work, which 2 threads share.
  const auto landed = [](int n, int) { return n == 1 ? 3e-3 : 2.25e-3; };
  run(t, 10, landed);
  EXPECT_EQ(t.trials(), 1);
  EXPECT_EQ(t.threads(), 2) << "the first window 3 times slower starts a trial";
  run(t, 40, landed);
  EXPECT_EQ(t.trials(), 2);
  EXPECT_EQ(t.chosen(), 2);
}
