// Preparation that reaches its target (lab/preparation_search.h): a
// specimen of spheres asked for Dr 0.2, 0.6 and 0.95 on the spheres' own
// index void ratios lands within 0.05 of each, with the friction the search
// chose; the search itself on a model of e(mu): failed trials, the ends;
// and the specimen the search lands on is, bit for bit, the one a test makes
// by itself at that friction (so a default run that the search prepares at
// the grain class's friction is the run a fixed friction made before).
#include "core/error.h"
#include "lab/index_densities.h"
#include "lab/preparation_search.h"
#include "lab/sand_presets.h"
#include "lab/deposition_friction.h"
#include "lab/oedometer.h"
#include "sphere_box.h"
#include "state_compare.h"
#include "tiny_box.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <utility>
#include <vector>

using namespace grainlab;

TEST(PreparationSearch, SpheresReachAWholeSpecimenVoidRatio) {
  // 250 spheres in a 6 x 6 x 5 d_max box: frictionless deposition gives a
  // whole-specimen e = 0.783, friction 0.12 gives 0.813 (measured; 0.016 and
  // 0.0375 gave 0.797 and 0.792: the scatter at one friction is about
  // 0.005). Asked for e = 0.80 +- 0.01, the search lands inside with a
  // friction between (measured: 2 trials, 0.12 then 0.0375).
  LabSpec spec = testing_support::sphere_spec();
  spec.specimen.indices = "lab";
  spec.specimen.void_ratio = 0.80;
  spec.specimen.tolerance = 0.01;
  const Preparation p = prepare_to_target(spec);
  ASSERT_TRUE(p.specimen);
  EXPECT_EQ(p.specimen->phase(), PreparationPhase::Consolidate);
  EXPECT_NEAR(p.specimen->achieved_void_ratio(), 0.80, 0.01);
  EXPECT_EQ(p.specimen->spec().specimen.deposition_friction, p.friction);
  EXPECT_EQ(p.trials.back().friction, p.friction);
  EXPECT_GT(p.friction, 0.0);
  EXPECT_LT(p.friction, kLoosestDepositionFriction);
  EXPECT_LE(p.trials.size(), 8u);
}

// Dr 0.2, 0.6 and 0.95 on the beads' own indices within 0.05 (issue 10
// item 3): the glass-beads sand preset in the demo's box (10 d_max across, 6
// high, 100 kPa) with the run's own-index box (10 x 8, one seed), as
// `grainlab run` prepares them. Measured 2026-12-05 (22 s on one thread,
// the machine shared): Dr 0.2 -> 0.178 at friction 2.55 (5 trials), 0.6 ->
// 0.632 (2), 0.95 -> 0.928 (1). With the search ending at the e_max
// friction 1.0 it stopped at Dr 0.26 for 0.2 (run as a mutation;
// lab/preparation_search.h, kLoosestSearchFriction). History: in a 6 d box the bulk e scattered by
// +-0.03 between preparations at one friction (a bulk of about 20 grains).
TEST(PreparationSearch, BeadsReachDr02To095OnTheirOwnIndices) {
  LabSpec spec;
  apply_sand_preset(spec, "glass-beads");
  spec.numerics.threads = 1;  // ctest runs two tests at once
  IndexDensityOptions box;
  box.seeds = 1;
  const IndexDensities own = measure_index_densities(spec, box);
  spec.specimen.indices = "own";
  spec.specimen.own_e_min = own.e_min;
  spec.specimen.own_e_max = own.e_max;
  for (double dr : {0.2, 0.6, 0.95}) {
    SCOPED_TRACE(dr);
    spec.specimen.relative_density = dr;
    const Preparation p = prepare_to_target(spec);
    ASSERT_TRUE(p.specimen);
    EXPECT_NEAR(p.specimen->achieved_own_relative_density(), dr, 0.05);
    std::printf("Dr %.2f: reached %.3f at deposition friction %.4f after %zu trial(s)\n", dr,
                p.specimen->achieved_own_relative_density(), p.friction, p.trials.size());
  }
}

TEST(PreparationSearch, UnreachableTargetStopsWithWhatItReached) {
  LabSpec spec = testing_support::sphere_spec();
  spec.specimen.void_ratio = 0.30;  // denser than spheres pack (e >= 0.5)
  spec.specimen.indices = "lab";
  PreparationSearchOptions o;
  o.max_trials = 3;
  try {
    prepare_to_target(spec, o);
    FAIL() << "an impossible void ratio was reached";
  } catch (const RunError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("could not reach e = 0.300"), std::string::npos) << msg;
    EXPECT_NE(msg.find("Trials:"), std::string::npos) << msg;
    EXPECT_NE(msg.find("To fix"), std::string::npos) << msg;
    EXPECT_NE(msg.find("frictionless"), std::string::npos) << msg;  // why: the densest end was tried
  }
}

namespace {

// A model of the preparation for the search alone: e grows linearly in
// u = mu / (mu + 0.1) from 0.78 (frictionless) to 0.86 (friction 1.0), and
// the trials whose friction lies in `fails` throw as a phase that never came
// to rest does.
struct ModelPreparation {
  std::vector<std::pair<double, double>> fails;  // friction ranges that fail
  int calls = 0;
  std::unique_ptr<SpecimenPreparation> operator()(const LabSpec&, double mu, PreparationTrial& out) {
    ++calls;
    for (const auto& [lo, hi] : fails)
      if (mu >= lo && mu <= hi) throw RunError("the compact phase did not come to rest in 400050 steps");
    const double u = mu / (mu + 0.1), u_max = 1.0 / 1.1;
    out.friction = mu;
    out.void_ratio = 0.78 + 0.08 * u / u_max;
    out.relative_density = NAN;
    out.steps = 1000;
    return nullptr;
  }
};

// Search options whose trials are `model`'s.
PreparationSearchOptions trials_of(const std::shared_ptr<ModelPreparation>& model) {
  PreparationSearchOptions o;
  o.trial = [model](const LabSpec& s, double mu, PreparationTrial& t) { return (*model)(s, mu, t); };
  return o;
}

LabSpec void_ratio_target(double e) {
  LabSpec s;
  s.specimen.void_ratio = e;
  s.specimen.tolerance = 0.002;
  return s;
}

}  // namespace

TEST(PreparationSearch, AFailedTrialIsListedAndTheSearchGoesOn) {
  // The first guess (friction 0.12) fails; the search tries another friction
  // and lands on e = 0.80 +- 0.002 (the model's friction 0.0294).
  auto model = std::make_shared<ModelPreparation>();
  model->fails = {{0.119, 0.121}};
  const Preparation p = prepare_to_target(void_ratio_target(0.80), trials_of(model));
  ASSERT_GE(p.trials.size(), 2u);
  EXPECT_NEAR(p.trials[0].friction, 0.12, 1e-9);
  EXPECT_NE(p.trials[0].error.find("did not come to rest"), std::string::npos);
  EXPECT_TRUE(std::isnan(p.trials[0].void_ratio));
  EXPECT_TRUE(p.trials.back().error.empty());
  EXPECT_NEAR(p.trials.back().void_ratio, 0.80, 0.002);
  EXPECT_NEAR(p.friction, p.trials.back().friction, 0);
}

TEST(PreparationSearch, TheLooseEndIsTriedAtTheEMaxFrictionFirst) {
  // The model's e at friction 0.12, 1.0 and 5 is 0.828, 0.860 and 0.866:
  // asked for e = 0.863, the search goes from its first guess to the e_max
  // preparation's friction (1.0), and only when that is still too dense to
  // the loosest end (kLoosestSearchFriction), then lands between.
  auto model = std::make_shared<ModelPreparation>();
  const Preparation p = prepare_to_target(void_ratio_target(0.863), trials_of(model));
  ASSERT_GE(p.trials.size(), 4u);
  EXPECT_NEAR(p.trials[0].friction, 0.12, 1e-9);
  EXPECT_NEAR(p.trials[1].friction, kLoosestDepositionFriction, 1e-9);
  EXPECT_NEAR(p.trials[2].friction, kLoosestSearchFriction, 1e-9);
  EXPECT_NEAR(p.trials.back().void_ratio, 0.863, 0.002);
  EXPECT_GT(p.friction, kLoosestDepositionFriction);
  EXPECT_LT(p.friction, kLoosestSearchFriction);
}

TEST(PreparationSearch, EveryTrialFailingStopsWithTheTrialsAndWhy) {
  auto model = std::make_shared<ModelPreparation>();
  model->fails = {{0.0, 1.0}};
  PreparationSearchOptions o = trials_of(model);
  o.max_trials = 4;
  try {
    prepare_to_target(void_ratio_target(0.80), o);
    FAIL() << "expected RunError";
  } catch (const RunError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("every trial failed"), std::string::npos) << m;
    EXPECT_NE(m.find("did not come to rest"), std::string::npos) << m;
    EXPECT_NE(m.find("closest e = none"), std::string::npos) << m;
  }
  EXPECT_EQ(model->calls, 4);
}

// The default friction (-1) is the search's. Its first trial at the rounded
// grains' measured friction (0.032, lab/deposition_friction.h) lands (the
// target and tolerance below make sure), and that specimen is the one a test
// built without the search makes (it deposits at the same first friction),
// bit for bit, through consolidation: the closed-box test's trial is made in
// its own box (preparation_spec).
TEST(PreparationSearch, TheLandingTrialIsTheSpecimenATestMakesAtThatFriction) {
  LabSpec spec = testing_support::tiny_box_spec();
  spec.grains.preset = "rounded";
  spec.specimen.deposition_friction = kSearchedDepositionFriction;
  spec.specimen.void_ratio = -1;
  spec.specimen.own_e_min = 0.41;
  spec.specimen.own_e_max = 0.67;
  spec.specimen.relative_density = 0.92;
  spec.specimen.relative_density_tolerance = 0.9;  // any packing lands: this test is about the bits
  spec.numerics.threads = 1;
  ASSERT_EQ(first_deposition_friction(spec), 0.032);
  const LabSpec ring = OedometerTest::preparation_spec(spec);
  EXPECT_EQ(ring.box.gap, 0.0);

  Preparation searched = prepare_to_target(ring);
  ASSERT_EQ(searched.trials.size(), 1u);
  EXPECT_EQ(searched.friction, 0.032);
  OedometerTest from_search(spec, std::move(searched.specimen));
  OedometerTest by_itself(spec);
  EXPECT_EQ(by_itself.preparation().spec().specimen.deposition_friction, 0.032);
  for (LabTest* t : {static_cast<LabTest*>(&from_search), static_cast<LabTest*>(&by_itself)})
    while (!t->loading()) t->advance(1000);  // prepared: compacted and consolidated
  EXPECT_GT(by_itself.world().state.step, 0);
  EXPECT_TRUE(testing_support::same_state_bits(from_search.world().state, by_itself.world().state));
}
