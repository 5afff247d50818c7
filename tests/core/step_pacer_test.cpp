// StepPacer (core/step_pacer.h): chunks sized to the period from the speed
// measured on the chunk before, within 1..max_steps.
#include "core/step_pacer.h"

#include <gtest/gtest.h>

#include <chrono>
#include <limits>
#include <thread>

using grainlab::StepPacer;

TEST(StepPacer, TheFirstChunkIsTheOneGiven) {
  EXPECT_EQ(StepPacer().next(), 1);
  EXPECT_EQ(StepPacer(100, 0.25, 100).next(), 100);
}

TEST(StepPacer, SlowStepsShrinkTheChunkToThePeriod) {
  // One step that took at least 20 ms: at most 50 steps/s, so a period of
  // 0.25 s holds at most 12.5 steps (the clock only makes it fewer).
  StepPacer pacer(100, 0.25, 100);
  pacer.next();
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  pacer.done(1);
  const int chunk = pacer.next();
  EXPECT_GE(chunk, 1);
  EXPECT_LE(chunk, 12);
}

TEST(StepPacer, AnInfinitePeriodKeepsTheLargestChunk) {
  StepPacer pacer(100, std::numeric_limits<double>::infinity(), 100);
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(pacer.next(), 100);
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
    pacer.done(100);
  }
}

TEST(StepPacer, AZeroPeriodMakesChunksOfOneStep) {
  StepPacer pacer(100, 0.0, 100);
  pacer.next();
  std::this_thread::sleep_for(std::chrono::milliseconds(1));
  pacer.done(100);
  EXPECT_EQ(pacer.next(), 1);
}
