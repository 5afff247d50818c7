// A box that would need more grains than memory allows is refused up front,
// with the grain count and the memory it would need (lab/specimen_budget.h).
#include "core/error.h"
#include "lab/direct_shear.h"
#include "lab/specimen_budget.h"

#include <gtest/gtest.h>

#include <string>

using namespace grainlab;

namespace {

LabSpec metre_box() {
  LabSpec s;
  s.grains.preset = "glass-beads";  // spheres: the shapes are quick to make
  s.grains.shapes = 2;
  s.box.length = s.box.width = s.box.height = 1.0;
  s.specimen.indices = "lab";
  s.specimen.deposition_friction = 0.1;
  return s;
}

bool has(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

}  // namespace

TEST(SpecimenBudget, MetreBoxIsRefusedWithCountAndMemory) {
  // About 2.3e9 grains of 0.77 mm (more than an Index holds) and, at the
  // bytes per grain of this build, terabytes.
  for (int built = 0; built < 2; ++built) {
    try {
      if (built) DirectShearTest t(metre_box());
      else check_specimen_fits(metre_box());
      FAIL() << "a 1 m box was accepted";
    } catch (const InputError& e) {
      const std::string msg = e.what();
      EXPECT_TRUE(has(msg, "needs about 2.")) << msg;  // 2.x e+09 grains
      EXPECT_TRUE(has(msg, "e+09 grains")) << msg;
      EXPECT_TRUE(has(msg, "GB of memory")) << msg;
      EXPECT_TRUE(has(msg, "Make the box smaller")) << msg;
      EXPECT_FALSE(has(msg, "half extents")) << msg;
    }
  }
}

TEST(SpecimenBudget, BytesPerGrainAndTheLimit) {
  // Structures of this build: a grain takes kilobytes, not bytes or megabytes.
  EXPECT_GT(bytes_per_grain(), 1000.0);
  EXPECT_LT(bytes_per_grain(), 100000.0);
  BoxSpec box;
  // 1e6 grains fit in 1 TB, not in 1 GB.
  EXPECT_NO_THROW(refuse_impossible_specimen(1e6, 1e12, box, 0.8e-3, "test"));
  EXPECT_THROW(refuse_impossible_specimen(1e6, 1e9, box, 0.8e-3, "test"), InputError);
  // Unknown memory: only the Index limit.
  EXPECT_NO_THROW(refuse_impossible_specimen(1e8, 0, box, 0.8e-3, "test"));
  EXPECT_THROW(refuse_impossible_specimen(3e9, 0, box, 0.8e-3, "test"), InputError);
}
