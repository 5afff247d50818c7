// Preparations kept as files (io/kept_preparations.h): a measurement of the
// index densities stopped during its dense preparation keeps it, and the
// next one goes on from there and ends where an uninterrupted measurement
// ends, to the bit (same steps, same e_min and e_max); the kept file then
// goes. A kept file of other inputs (another seed) is not taken. A trial of
// the friction search, stopped and gone on from, ends as an uninterrupted
// one; kept at its end, it is taken back at once; the run's first
// checkpoint removes the trials.
#include "io/kept_preparations.h"
#include "io_test_helpers.h"
#include "lab/preparation.h"
#include "lab/index_densities.h"
#include "lab/preparation_search.h"
#include "lab/sphere_box.h"

#include "core/error.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <limits>

using namespace grainlab;

TEST(KeptPreparations, AStoppedIndexMeasurementGoesOnFromItsKeptPreparationToTheSameResult) {
  const LabSpec spec = testing_support::sphere_spec();
  const IndexDensityOptions o = testing_support::small_index_box();
  const IndexDensities straight = measure_index_densities(spec, o);
  ASSERT_TRUE(straight.settled());
  // Stopped below at the 43rd check (one every 100 steps: an infinite
  // stop_check_period_s keeps every batch at 100 steps): step 4300, in the
  // compaction (measured: deposition to step 4200, compaction to 11700),
  // where the protocol's phase, phase start and servo must come back too.
  ASSERT_GT(straight.dense.front().steps, 6000);

  test::IoTempDir dir;
  int asked = 0;
  KeptPreparations stopping(dir.path, [&] { return ++asked == 43; });
  stopping.stop_check_period_s = std::numeric_limits<double>::infinity();
  const std::string name = index_preparation_name(true, spec.seed);
  EXPECT_EQ(stopping.file(name).filename(), "index_e_min_seed3.bin");
  EXPECT_THROW(measure_index_densities(spec, o, {}, {}, {}, &stopping), Stopped);
  ASSERT_TRUE(std::filesystem::exists(stopping.file(name)));

  // Another seed's preparation does not take it.
  LabSpec other = spec;
  other.seed = 4;
  {
    KeptPreparations files(dir.path);
    const LabSpec prepared = index_preparation_spec(other, o, true, other.seed);
    SpecimenPreparation t(prepared);
    EXPECT_LT(files.restore(t, name, prepared), 0);
    const LabSpec same = index_preparation_spec(spec, o, true, spec.seed);
    SpecimenPreparation u(same);
    EXPECT_GE(files.restore(u, name, same), 0);
    EXPECT_EQ(u.world().state.step, 4300);
    EXPECT_EQ(u.phase_name(), "compact");
  }

  std::vector<std::string> lines;
  KeptPreparations going_on(dir.path);
  const IndexDensities resumed =
      measure_index_densities(spec, o, [&](const std::string& l) { lines.push_back(l); }, {}, {}, &going_on);
  ASSERT_FALSE(lines.empty());
  EXPECT_NE(lines.front().find("going on from step 4300"), std::string::npos) << lines.front();
  EXPECT_EQ(resumed.dense.front().steps, straight.dense.front().steps);
  EXPECT_EQ(resumed.e_min, straight.e_min);
  EXPECT_EQ(resumed.e_max, straight.e_max);
  EXPECT_EQ(resumed.dense.front().whole_void_ratio, straight.dense.front().whole_void_ratio);
  EXPECT_FALSE(std::filesystem::exists(going_on.file(name)));
}

// Where 100 steps take longer than stop_check_period_s (faceted grains take
// seconds), the batches shrink so that a stop signal is seen within that
// period. With a period of 0 every batch after the first (100 steps) is one
// step: the third look at the stop comes at step 102.
TEST(KeptPreparations, AShortStopCheckPeriodLooksAtTheStopAfterEveryStep) {
  const LabSpec spec = testing_support::sphere_spec();
  const double mu = 0.05;
  test::IoTempDir dir;
  int asked = 0;
  KeptPreparations stopping(dir.path, [&] { return ++asked == 3; });
  stopping.stop_check_period_s = 0;
  PreparationTrial stopped;
  EXPECT_THROW(trial_preparation(spec, mu, stopped, &stopping), Stopped);
  LabSpec s = spec;
  s.specimen.deposition_friction = mu;
  SpecimenPreparation kept(s);
  ASSERT_GE(KeptPreparations(dir.path).restore(kept, trial_preparation_name(mu), s), 0);
  EXPECT_EQ(kept.world().state.step, 102);
}

TEST(KeptPreparations, AStoppedTrialGoesOnToTheSameSpecimenAndAFinishedOneIsTakenBack) {
  const LabSpec spec = testing_support::sphere_spec();
  const double mu = 0.05;
  PreparationTrial straight;
  const auto t0 = trial_preparation(spec, mu, straight);

  test::IoTempDir dir;
  int asked = 0;
  KeptPreparations stopping(dir.path, [&] { return ++asked == 20; });
  stopping.stop_check_period_s = std::numeric_limits<double>::infinity();
  PreparationTrial stopped;
  EXPECT_THROW(trial_preparation(spec, mu, stopped, &stopping), Stopped);
  const std::filesystem::path file = stopping.file(trial_preparation_name(mu));
  EXPECT_EQ(file.filename(), "trial_friction_0.05000000.bin");
  ASSERT_TRUE(std::filesystem::exists(file));

  KeptPreparations going_on(dir.path);
  PreparationTrial resumed;
  std::vector<std::string> said;
  const auto t1 = trial_preparation(spec, mu, resumed, &going_on, [&](const std::string& l) { said.push_back(l); });
  ASSERT_EQ(said.size(), 1u + static_cast<std::size_t>(straight.steps / 10000));  // + a line every 10,000 steps
  EXPECT_NE(said.front().find("going on from step 2000"), std::string::npos) << said.front();
  for (std::size_t k = 1; k < said.size(); ++k) {  // "...: step 10050, compact phase, ..."
    const std::size_t at = said[k].find(": step ");
    ASSERT_NE(at, std::string::npos) << said[k];
    const long step = std::stol(said[k].substr(at + 7));
    EXPECT_GE(step, 10000 * static_cast<long>(k)) << said[k];
    EXPECT_LT(step, 10000 * static_cast<long>(k) + 100) << said[k];  // within a batch of 100 steps of it
  }
  EXPECT_EQ(resumed.steps, straight.steps);
  EXPECT_EQ(resumed.void_ratio, straight.void_ratio);
  EXPECT_EQ(t1->world().state.bodies.back().x, t0->world().state.bodies.back().x);
  ASSERT_TRUE(std::filesystem::exists(file));  // kept at its end

  // Taken back at once: nothing stepped (a stop asked for now would throw).
  KeptPreparations finished(dir.path, [] { return true; });
  PreparationTrial again;
  const auto t2 = trial_preparation(spec, mu, again, &finished);
  EXPECT_EQ(again.steps, straight.steps);
  EXPECT_EQ(again.void_ratio, straight.void_ratio);
  // Another friction does not take it.
  PreparationTrial other;
  EXPECT_THROW(trial_preparation(spec, 0.06, other, &finished), Stopped);

  // Written for other grains (the generator changed since): not taken back.
  {
    LabSpec s = spec;
    s.specimen.deposition_friction = mu;
    SpecimenPreparation fresh(s);
    EXPECT_GE(KeptPreparations(dir.path).restore(fresh, trial_preparation_name(mu), s), 0);
    std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
    f.seekg(12);
    const char byte = static_cast<char>(f.get() ^ 0x5a);
    f.seekp(12);
    f.put(byte);
    f.close();
    SpecimenPreparation other(s);
    EXPECT_LT(KeptPreparations(dir.path).restore(other, trial_preparation_name(mu), s), 0);
  }

  drop_kept_trials(dir.path);
  EXPECT_FALSE(std::filesystem::exists(file));
}
