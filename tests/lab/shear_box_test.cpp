// The direct shear box: its gap between the halves stays closed while the
// specimen is made and opens when the shear begins; a grain that leaves the
// box stops the run with its name, place and time.
#include "core/error.h"
#include "dynamics/world.h"
#include "geometry/primitives.h"
#include "lab/direct_shear.h"
#include "lab/shear_box.h"
#include "tiny_box.h"

#include <gtest/gtest.h>

#include <string>

using namespace grainlab;

namespace {

BoxSpec plate_box() {
  BoxSpec b;
  b.length = b.width = 5e-3;
  b.height = 4e-3;
  b.gap = 0.3e-3;
  return b;
}

// A 1 x 1 x 0.2 mm plate, thinner than the 0.3 mm gap, flies edge-on at the
// gap's height towards the +x side of the box, without gravity; returns
// where it is after it has had time to cross the box twice.
Index plate_outside_after_flight(bool gap_open) {
  const BoxSpec box = plate_box();
  World w;
  Material m;
  m.youngs_modulus = 1e8;
  m.restitution = 0.5;
  m.friction = 0;
  const Index mat = w.model.add_material(m);
  w.model.gravity.setZero();
  const Index plate = w.model.add_mesh_shape(box_mesh(0.5e-3, 0.5e-3, 0.1e-3), "plate");
  w.add_body(plate, mat, 1.0, Vec3(0.5 * box.length - 1e-3, 0, 0.5 * box.height), Quat::Identity(),
             Vec3(2.0, 0, 0));
  build_shear_box(w, box, box.height, mat);
  if (gap_open) open_shear_box_gap(w, box);
  const double dt = 0.2 * w.critical_time_step();
  for (double t = 0; t < 2 * box.length / 2.0; t += dt) w.step(dt);
  return grain_outside_shear_box(w);
}

}  // namespace

TEST(ShearBox, AGrainThinnerThanTheGapStaysInWhileTheGapIsClosedAndLeavesOnceItIsOpen) {
  EXPECT_EQ(plate_outside_after_flight(false), -1);
  EXPECT_EQ(plate_outside_after_flight(true), 0);
}

TEST(ShearBox, TheGapOpensWhenTheShearBeginsAndTheUpperHalfKeepsItsTop) {
  LabSpec spec = testing_support::tiny_box_spec();
  DirectShearTest t(spec);
  const World& w = t.world();
  const double H = spec.box.height, gap = spec.box.gap;
  const double top = w.state.walls[UpperXm].x.z() + w.model.walls[UpperXm].half.z() + gap;
  EXPECT_NEAR(w.state.walls[LowerXm].x.z() + w.model.walls[LowerXm].half.z(), 0.5 * H - 0.5 * gap, 1e-15);
  for (Index r = UpperXm; r <= UpperYp; ++r)  // resting on the lower half
    EXPECT_NEAR(w.state.walls[r].x.z() - w.model.walls[r].half.z(), 0.5 * H - 0.5 * gap, 1e-15) << r;
  while (t.phase() < ShearPhase::Shear) ASSERT_TRUE(t.advance(1000));
  EXPECT_EQ(grain_outside_shear_box(w), -1);
  for (Index r = UpperXm; r <= UpperYp; ++r) {
    EXPECT_NEAR(w.state.walls[r].x.z() - w.model.walls[r].half.z(), 0.5 * H + 0.5 * gap, 1e-15) << r;
    EXPECT_NEAR(w.state.walls[r].x.z() + w.model.walls[r].half.z(), top, 1e-15) << r;
  }
}

TEST(ShearBox, AGrainThatLeavesTheBoxStopsTheRunSayingWhichWhereAndWhen) {
  DirectShearTest t(testing_support::tiny_box_spec());
  World& w = t.world();
  w.state.bodies[7].x = Vec3(0.5 * t.spec().box.length + 3e-3, 0, 1e-3);  // on the floor, past the +x slab
  try {
    t.advance(kCheckEvery);
    FAIL() << "no error";
  } catch (const RunError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("grain 7 left the shear box in the deposit phase"), std::string::npos) << what;
    EXPECT_NE(what.find("mm thick at its thinnest"), std::string::npos) << what;
    EXPECT_NE(what.find("time_step_fraction"), std::string::npos) << what;
  }
}
