// Index preparations kept as files (io/index_preparation_files.h): a
// measurement stopped during its dense preparation keeps it, and the next
// one goes on from there and ends where an uninterrupted measurement ends,
// to the bit (same steps, same e_min and e_max); the kept file then goes.
// A kept file of other inputs (another seed) is not taken.
#include "io/index_preparation_files.h"
#include "io_test_helpers.h"
#include "lab/direct_shear.h"
#include "lab/sphere_box.h"

#include "core/error.h"

#include <gtest/gtest.h>

#include <filesystem>

using namespace grainlab;

TEST(IndexPreparationFiles, AStoppedMeasurementGoesOnFromItsKeptPreparationToTheSameResult) {
  const DirectShearSpec spec = testing_support::sphere_spec();
  const IndexDensityOptions o = testing_support::small_index_box();
  const IndexDensities straight = measure_index_densities(spec, o);
  ASSERT_TRUE(straight.settled());
  // Stopped below at the 43rd check (one every 100 steps): step 4300, in the
  // compaction (measured: deposition to step 4200, compaction to 11700),
  // where the protocol's phase, phase start and servo must come back too.
  ASSERT_GT(straight.dense.front().steps, 6000);

  test::IoTempDir dir;
  int asked = 0;
  IndexPreparationFiles stopping(dir.path, [&] { return ++asked == 43; });
  const std::filesystem::path kept = stopping.file(index_preparation_spec(spec, o, true, spec.seed));
  EXPECT_EQ(kept.filename(), "index_e_min_seed3.bin");
  EXPECT_THROW(measure_index_densities(spec, o, {}, {}, {}, &stopping), Stopped);
  ASSERT_TRUE(std::filesystem::exists(kept));

  // Another seed's preparation does not take it.
  DirectShearSpec other = spec;
  other.seed = 4;
  {
    IndexPreparationFiles files(dir.path);
    const DirectShearSpec prepared = index_preparation_spec(other, o, true, other.seed);
    DirectShearTest t(prepared);
    EXPECT_LT(files.restore(t, prepared), 0);
    const DirectShearSpec same = index_preparation_spec(spec, o, true, spec.seed);
    DirectShearTest u(same);
    EXPECT_GE(files.restore(u, same), 0);
    EXPECT_EQ(u.world().state.step, 4300);
    EXPECT_EQ(u.phase_name(), "compact");
  }

  std::vector<std::string> lines;
  IndexPreparationFiles going_on(dir.path);
  const IndexDensities resumed =
      measure_index_densities(spec, o, [&](const std::string& l) { lines.push_back(l); }, {}, {}, &going_on);
  ASSERT_FALSE(lines.empty());
  EXPECT_NE(lines.front().find("going on from step 4300"), std::string::npos) << lines.front();
  EXPECT_EQ(resumed.dense.front().steps, straight.dense.front().steps);
  EXPECT_EQ(resumed.e_min, straight.e_min);
  EXPECT_EQ(resumed.e_max, straight.e_max);
  EXPECT_EQ(resumed.dense.front().whole_void_ratio, straight.dense.front().whole_void_ratio);
  EXPECT_FALSE(std::filesystem::exists(kept));
}
