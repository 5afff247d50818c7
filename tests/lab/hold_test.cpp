// The lab-test recipe, proved from this file alone: the smallest extra lab
// test ("hold": prepares its specimen, then holds it under the cap for
// hold.steps steps), with one config key of its own, registered from the test
// binary (lab/lab_registry.h), read by the config (its key, its default, its
// check, a misspelt key's suggestion) and run through make_lab_test. It
// writes only what every test has (lab/lab_test.h: phases, loading, progress,
// checkpoint bytes); series, summary, notes, volume and stress are the
// defaults of LabTest and PreparedTest.
#include "core/error.h"
#include "io/config.h"
#include "lab/lab_registry.h"
#include "lab/prepared_test.h"
#include "tiny_box.h"

#include <gtest/gtest.h>

#include <string>

using namespace grainlab;

namespace {

struct HoldSpec {
  int steps = 100;  // steps held after the preparation
};

class HoldTest final : public PreparedTest {
 public:
  explicit HoldTest(const LabSpec& spec) : PreparedTest(spec, std::make_unique<SpecimenPreparation>(spec)) {}

  static LabTestKeys keys() {
    LabTestKeys k;
    k.table = {"hold", "holding the prepared specimen under the cap"};
    k.fields = {{"hold", "steps", "steps held after the preparation",
                 [](LabSpec& s) -> SpecFieldRef { return &s.settings<HoldSpec>().steps; }}};
    k.validate = [](LabSpec& s, const SpecNeed& need) {
      int& n = s.settings<HoldSpec>().steps;
      need(n >= 1, "hold.steps", &n, "at least 1");
    };
    return k;
  }

  bool advance(int max_steps) override {
    if (!prep_->prepared()) {
      if (!prep_->advance(max_steps)) start_ = world().state.step, prep_->hold_cap(true);
      return true;
    }
    for (int i = 0; i < max_steps && !done(); ++i) world().step(time_step());
    return !done();
  }
  int phase_index() const override { return static_cast<int>(prep_->phase()) + (done() ? 1 : 0); }
  std::string phase_name() const override { return done() ? "done" : prep_->phase_name(); }
  bool loading() const override { return prep_->prepared() && !done(); }
  bool done() const override { return prep_->prepared() && world().state.step - start_ >= steps(); }
  std::int64_t loading_start_step() const override { return start_; }
  double progress() const override { return prep_->prepared() ? double(world().state.step - start_) / steps() : 0; }
  std::vector<std::uint8_t> save() const override {
    ByteWriter b;
    prep_->save(b);
    b.i64(start_);
    return std::move(b.bytes);
  }
  void load(std::span<const std::uint8_t> bytes) override {
    ByteReader r(bytes, "the hold test's state");
    prep_->load(r);
    start_ = r.i64();
    r.expect_end();
    prep_->hold_cap(prep_->prepared());
  }

 private:
  int steps() const { return spec_.settings<HoldSpec>().steps; }

  std::int64_t start_ = 0;
};

// The one registration line (once per process).
void register_hold() {
  static const bool registered = [] {
    register_lab_test(lab_test_entry<HoldTest>("hold"));
    return true;
  }();
  (void)registered;
}

}  // namespace

TEST(LabTestRecipe, AHoldTestRegisteredHereReadsItsOwnKeyAndRuns) {
  register_hold();
  const LabSpec spec = parse_config("test = \"hold\"\n[hold]\nsteps = 7\n", "hold.toml");
  EXPECT_EQ(spec.settings<HoldSpec>().steps, 7);
  EXPECT_EQ(parse_config("test = \"hold\"\n", "hold.toml").settings<HoldSpec>().steps, 100);  // its default

  // Its own table, and only its, in its commented defaults; its check; a misspelt key's suggestion.
  const std::string defaults = default_config_toml("hold");
  EXPECT_NE(defaults.find("[hold]\nsteps = 100"), std::string::npos) << defaults;
  EXPECT_EQ(defaults.find("\n[shear]\n"), std::string::npos);
  EXPECT_NE(defaults.find("runs/hold"), std::string::npos);
  try {
    parse_config("test = \"hold\"\n[hold]\nsteps = 0\n", "hold.toml");
    FAIL() << "hold.steps = 0 was taken";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("hold.steps = 0 is impossible: it must be at least 1"), std::string::npos)
        << e.what();
  }
  try {
    parse_config("[hold]\nstep = 3\n", "hold.toml");
    FAIL() << "hold.step was taken";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("Did you mean 'steps'?"), std::string::npos) << e.what();
  }

  // Made by name with the tiny box's specimen, and one advance.
  LabSpec tiny = testing_support::tiny_box_spec();
  tiny.test = "hold";
  tiny.settings<HoldSpec>().steps = 7;
  const std::unique_ptr<LabTest> t = make_lab_test(tiny.test, tiny);
  EXPECT_TRUE(t->advance(10));
  EXPECT_EQ(t->world().state.step, 10);
  EXPECT_EQ(t->phase_name(), "deposit");
  // The defaults: no series, the preparation's summary and status, the cap's stress over the volume below it.
  EXPECT_TRUE(t->series().empty());
  EXPECT_TRUE(t->series_columns().empty());
  EXPECT_TRUE(t->reference().empty());
  EXPECT_EQ(t->summary().size(), static_cast<const PreparedTest&>(*t).preparation().summary().size());
  EXPECT_FALSE(t->summary().empty());
  EXPECT_EQ(t->status_line(), static_cast<const PreparedTest&>(*t).preparation().status_line());
  const World& w = t->world();
  EXPECT_EQ(t->specimen_volume(), tiny.box.length * tiny.box.width * w.state.walls[Cap].x.z());
  EXPECT_EQ(t->boundary_stress(), w.state.walls[Cap].force.z() / (tiny.box.length * tiny.box.width));
  EXPECT_EQ(t->result_line(), "done");
}
