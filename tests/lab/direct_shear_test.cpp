// The direct shear protocol: a run restored from a checkpoint continues bit
// for bit like the uninterrupted one.
#include "io/checkpoint.h"
#include "lab/direct_shear.h"
#include "tiny_box.h"
#include "state_compare.h"

#include <gtest/gtest.h>


using namespace grainlab;

namespace {

// A very small box of coarse grains: enough to exercise the protocol quickly.
using testing_support::tiny_box_spec;

// Runs `spec` for 2 x batches x steps; a copy restored from the checkpoint
// taken halfway (through the real encoding, as `grainlab run --resume` does)
// must end with the same state and series, bit for bit.
void expect_restore_continues_bit_for_bit(const LabSpec& spec, int batches, int steps,
                                          bool concave = false) {
  DirectShearTest a(spec);
  for (int i = 0; i < batches; ++i) a.advance(steps);
  if (concave) {
    ASSERT_FALSE(a.world().state.piece_caches.empty());
  }
  const std::vector<std::uint8_t> bytes = encode_checkpoint(a.world().state, a.save(), 42);
  for (int i = 0; i < batches; ++i) a.advance(steps);

  DirectShearTest b(spec);
  Checkpoint ck = decode_checkpoint(bytes, "in-memory");
  b.world().state = std::move(ck.state);
  b.load(ck.protocol);
  for (int i = 0; i < batches; ++i) b.advance(steps);

  EXPECT_GT(a.world().state.contacts.size(), 0u);
  EXPECT_EQ(a.phase(), b.phase());
  EXPECT_TRUE(testing_support::same_state_bits(a.world().state, b.world().state));
  EXPECT_EQ(a.series(), b.series());
}

}  // namespace

TEST(DirectShear, CheckpointRestoreContinuesBitForBit) { expect_restore_continues_bit_for_bit(tiny_box_spec(), 4, 250); }

// The same with dented grains (convexity 0.85, collided as convex pieces):
// their pairs keep their piece pairs' caches (CandidatePair::pieces), which
// the checkpoint carries too. (Concave grains' step is about half of convex
// ones', time_step.h: the grains first touch after more than 600 steps.)
TEST(DirectShear, CheckpointRestoreOfConcaveGrainsContinuesBitForBit) {
  LabSpec spec = tiny_box_spec();
  spec.grains.convexity = 0.85;
  expect_restore_continues_bit_for_bit(spec, 2, 600, true);
}

TEST(DirectShear, GrainCountFollowsTheTargetVoidRatio) {
  const LabSpec spec = tiny_box_spec();
  DirectShearTest t(spec);
  const double box = spec.box.length * spec.box.width * spec.box.height;
  const double e = box / t.solid_volume() - 1;
  // The count is rounded to whole grains of a random mix of shapes.
  EXPECT_NEAR(e, spec.target_void_ratio(), 0.15);
  EXPECT_GT(t.world().model.bodies.size(), 20u);
  EXPECT_EQ(t.phase(), ShearPhase::Deposit);
}
