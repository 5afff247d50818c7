// A LabTest saved mid-phase (its protocol bytes through a real checkpoint,
// with the State) and restored into a fresh test continues bit for bit:
// in the compaction (servo active, integral non-zero, deposition overrides
// re-derived from the phase) and in shear (series rows, reference grains).
// Only the LabTest interface and the registry are used, as io and apps do.
#include "io/checkpoint.h"
#include "lab/direct_shear.h"
#include "lab/lab_test.h"
#include "lab/oedometer.h"
#include "lab/triaxial.h"
#include "state_compare.h"
#include "sphere_box.h"
#include "tiny_box.h"

#include <gtest/gtest.h>

using namespace grainlab;

namespace {

// Runs `a` until `reached` holds, saves, continues both the original and a
// restored copy by the same steps, and compares them.
template <typename Reached>
void save_restore_continue(const LabSpec& spec, Reached reached, int steps) {
  std::unique_ptr<LabTest> a = make_lab_test(spec.test, spec);
  while (!reached(*a)) ASSERT_TRUE(a->advance(7)) << "the test ended before the state to save";
  const std::vector<std::uint8_t> bytes = encode_checkpoint(a->world().state, a->save(), 7);
  for (int i = 0; i < steps; i += 10) a->advance(10);

  std::unique_ptr<LabTest> b = make_lab_test(spec.test, spec);
  Checkpoint ck = decode_checkpoint(bytes, "in-memory");
  b->world().state = std::move(ck.state);
  b->load(ck.protocol);
  for (int i = 0; i < steps; i += 10) b->advance(10);

  EXPECT_EQ(a->phase_name(), b->phase_name());
  EXPECT_EQ(a->world().state.step, b->world().state.step);
  EXPECT_TRUE(testing_support::same_state_bits(a->world().state, b->world().state));
  EXPECT_EQ(a->save(), b->save()) << "the protocol bytes differ";  // rows included, bit for bit (nan too)
  EXPECT_EQ(a->series().size(), b->series().size());
}

}  // namespace

TEST(LabTestSaveRestore, MidCompactionWithTheServoActive) {
  const LabSpec spec = testing_support::tiny_box_spec();
  save_restore_continue(
      spec,
      [](const LabTest& t) {
        const auto& d = dynamic_cast<const DirectShearTest&>(t);
        return d.phase() == ShearPhase::Compact && d.servo_integral() != 0 &&
               d.world().state.step % kCheckEvery != 0;
      },
      600);
}

TEST(LabTestSaveRestore, MidShear) {
  LabSpec spec = testing_support::tiny_box_spec();
  spec.settings<ShearSpec>().final_strain = 0.02;
  save_restore_continue(
      spec, [](const LabTest& t) { return t.loading() && t.series().size() >= 3; }, 600);
}

TEST(LabTestSaveRestore, OedometerMidStageAfterARow) {
  // The servo of the second stage, its calm counter and window, the stage rows.
  // Spheres (cheap): the protocol is the same for any grain.
  LabSpec spec = testing_support::loose_bead_spec("oedometer");
  spec.settings<OedometerSpec>().stresses = {200e3, 400e3};
  save_restore_continue(
      spec,
      [](const LabTest& t) { return t.loading() && t.series().size() == 2 && t.world().state.step % kCheckEvery != 0; },
      600);
}

TEST(LabTestSaveRestore, OedometerAtAConstantRateUnloading) {
  // The cap's speed (re-derived from H_0), the last row's stress, the rows;
  // saved on the way back down, after the cap has turned.
  LabSpec spec = testing_support::loose_bead_spec("oedometer");
  spec.settings<OedometerSpec>().stresses = {200e3, 100e3};
  spec.settings<OedometerSpec>().loading = "constant-rate";
  save_restore_continue(
      spec,
      [](const LabTest& t) {
        return t.loading() && !t.series().empty() && t.series().back()[OedometerColumn::Stage] == 2 && t.world().state.step % 7 != 0;
      },
      600);
}

TEST(LabTestSaveRestore, TriaxialMidShear) {
  // The four side servos and the cap's speed, the side stress sums, the rows.
  LabSpec spec = testing_support::loose_bead_spec("triaxial");
  spec.settings<TriaxialSpec>().final_strain = 0.02;
  spec.output.strain_interval = 0.002;
  save_restore_continue(
      spec, [](const LabTest& t) { return t.loading() && t.series().size() >= 2 && t.world().state.step % 7 != 0; },
      600);
}

TEST(LabTestSaveRestore, RegistryMakesByNameAndRefusesUnknownNames) {
  const LabSpec spec = testing_support::tiny_box_spec();
  EXPECT_EQ(make_lab_test("direct-shear", spec)->phase_name(), "deposit");
  EXPECT_EQ(make_lab_test("oedometer", spec)->phase_name(), "deposit");
  EXPECT_EQ(make_lab_test("triaxial", spec)->phase_name(), "deposit");
  EXPECT_THROW(make_lab_test("simple-shear", spec), InputError);
  // The built-in tests first (a program may register more: hold_test.cpp).
  const std::vector<std::string> names = lab_test_names();
  ASSERT_GE(names.size(), 3u);
  EXPECT_EQ(std::vector<std::string>(names.begin(), names.begin() + 3),
            (std::vector<std::string>{"direct-shear", "oedometer", "triaxial"}));
}

TEST(LabTestSaveRestore, EveryTestsWorldTakesTheSpecsThreadCount) {
  // Set where the World is built (lab/preparation.h), never written afterwards.
  LabSpec spec = testing_support::tiny_box_spec();
  spec.numerics.threads = 3;
  for (const char* name : {"direct-shear", "oedometer", "triaxial"}) {
    std::unique_ptr<LabTest> t = make_lab_test(name, spec);
    EXPECT_EQ(t->world().settings.threads, 3) << name;
    t->advance(10);
    EXPECT_EQ(t->world().settings.threads, 3) << name;
  }
}

TEST(LabTestSaveRestore, TruncatedProtocolBytesAreRefused) {
  const LabSpec spec = testing_support::tiny_box_spec();
  std::unique_ptr<LabTest> a = make_lab_test("direct-shear", spec);
  a->advance(100);
  std::vector<std::uint8_t> bytes = a->save();
  bytes.pop_back();
  std::unique_ptr<LabTest> b = make_lab_test("direct-shear", spec);
  try {
    b->load(bytes);
    FAIL() << "truncated bytes were accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("direct shear protocol state is corrupted (it ends early)"),
              std::string::npos)
        << e.what();
  }
}
