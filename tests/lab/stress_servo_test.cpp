// The stress servo: it brings the stress on a cap pressing a sphere onto a
// floor to the target, comes down at its speed limit while it touches
// nothing, and its saved integral restores a controller that continues bit
// for bit.
#include "lab/stress_servo.h"
#include "state_compare.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace grainlab;

namespace {

constexpr double kArea = 4e-6;      // m^2
constexpr double kTarget = 2.5e4;   // Pa: 0.1 N on the sphere
constexpr double kLimit = 1e-3;     // m/s

// A sphere of radius 1 mm on the floor, the cap (wall 1) `gap` above its top.
World sphere_under_cap(double gap) {
  World w;
  w.model.gravity = Vec3::Zero();
  w.model.density_scale = 100;
  const Index s = w.model.add_sphere_shape(1e-3);
  w.add_body(s, 0, 1.0, Vec3(0, 0, 1e-3));
  w.add_plane(Vec3::Zero(), Vec3::UnitZ(), 0, "floor");
  w.add_plane(Vec3(0, 0, 2e-3 + gap), -Vec3::UnitZ(), 0, "cap");
  return w;
}

}  // namespace

TEST(StressServo, ComesDownAtTheLimitUntilItTouches) {
  World w = sphere_under_cap(1e-5);
  StressServo servo(1, kArea, kTarget, kLimit);
  w.add_controller([&](World& ww, double dt) { servo.control(ww, dt); });
  const double dt = 1e-6;
  w.step(dt);
  EXPECT_EQ(w.state.walls[1].v.z(), -kLimit);
  EXPECT_EQ(servo.integral(), 0.0);
  EXPECT_NEAR(w.state.walls[1].x.z(), 2e-3 + 1e-5 - kLimit * dt, 1e-15);
}

TEST(StressServo, HoldsTheTargetStress) {
  World w = sphere_under_cap(1e-6);
  StressServo servo(1, kArea, kTarget, kLimit);
  w.add_controller([&](World& ww, double dt) { servo.control(ww, dt); });
  const double dt = 0.2 * w.critical_time_step();
  for (int i = 0; i < 40000; ++i) w.step(dt);
  EXPECT_NEAR(servo.stress(w) / kTarget, 1.0, 1e-3);
  EXPECT_NEAR(w.state.walls[1].force.z(), kTarget * kArea, 1e-3 * kTarget * kArea);
  EXPECT_NE(servo.integral(), 0.0);
}

TEST(StressServo, SavedIntegralContinuesBitForBit) {
  const auto make = [] { return sphere_under_cap(1e-6); };
  World a = make();
  StressServo sa(1, kArea, kTarget, kLimit);
  a.add_controller([&](World& ww, double dt) { sa.control(ww, dt); });
  const double dt = 0.2 * a.critical_time_step();
  for (int i = 0; i < 3000; ++i) a.step(dt);
  ASSERT_NE(sa.integral(), 0.0);
  ByteWriter out;
  sa.save(out);
  const State saved = a.state;
  for (int i = 0; i < 2000; ++i) a.step(dt);

  World b = make();
  b.state = saved;
  StressServo sb(1, kArea, kTarget, kLimit);
  ByteReader in(out.bytes, "servo bytes");
  sb.load(in);
  in.expect_end();
  b.add_controller([&](World& ww, double dt_) { sb.control(ww, dt_); });
  for (int i = 0; i < 2000; ++i) b.step(dt);
  EXPECT_EQ(sa.integral(), sb.integral());
  EXPECT_TRUE(testing_support::same_state_bits(a.state, b.state));

  // Without the integral, the continuation differs: the test can fail.
  World c = make();
  c.state = saved;
  StressServo sc(1, kArea, kTarget, kLimit);
  c.add_controller([&](World& ww, double dt_) { sc.control(ww, dt_); });
  for (int i = 0; i < 2000; ++i) c.step(dt);
  EXPECT_FALSE(testing_support::same_state_bits(a.state, c.state));
}
