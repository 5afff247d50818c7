// Phase overrides: a lab phase changes the gravity and a material's friction
// the step uses without touching the Model, and friction still mixes by the
// minimum of the two materials. A sliding block checks the friction the step
// applies against Coulomb's law: a = g (sin t - mu cos t).
#include "core/error.h"
#include "dynamics/world.h"
#include "geometry/primitives.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace grainlab;

TEST(PhaseOverrides, GravityOverrideDrivesTheStepAndLeavesTheModel) {
  World w;
  const Index s = w.model.add_sphere_shape(1e-3);
  w.add_body(s, 0, 1.0, Vec3::Zero());
  const Vec3 g(1.0, -2.0, -300.0);
  PhaseOverrides o;
  o.gravity = g;
  w.set_overrides(o);
  const double dt = 1e-4;
  w.step(dt);
  // Semi-implicit Euler from rest: v = g dt.
  EXPECT_EQ(w.state.bodies[0].v, g * dt);
  EXPECT_EQ(w.model.gravity, Vec3(0, 0, -9.81));
  w.set_overrides({});
  const Vec3 v1 = w.state.bodies[0].v;
  w.step(dt);
  EXPECT_EQ(w.state.bodies[0].v, v1 + w.model.gravity * dt);
}

TEST(PhaseOverrides, FrictionOverrideMixesByTheMinimum) {
  World w;
  Material a, b;
  a.friction = 0.5, b.friction = 0.3;
  const Index ma = w.model.add_material(a), mb = w.model.add_material(b);
  const Index s = w.model.add_sphere_shape(1e-3);
  w.add_body(s, ma, 1.0, Vec3::Zero());
  w.step(1e-6);  // prepares the pair table
  EXPECT_EQ(w.pair(ma, ma).friction, 0.5);
  EXPECT_EQ(w.pair(ma, mb).friction, 0.3);
  PhaseOverrides o;
  o.friction = {{ma, 0.1}};
  w.set_overrides(o);
  EXPECT_EQ(w.pair(ma, ma).friction, 0.1);
  EXPECT_EQ(w.pair(ma, mb).friction, 0.1);
  EXPECT_EQ(w.pair(mb, ma).friction, 0.1);
  EXPECT_EQ(w.pair(mb, mb).friction, 0.3);
  EXPECT_EQ(w.model.materials[ma].friction, 0.5);  // the Model is unchanged
  EXPECT_EQ(w.model.pair(ma, ma).friction, 0.5);
  // Every other coefficient is the Model's.
  EXPECT_EQ(w.pair(ma, mb).c, w.model.pair(ma, mb).c);
  w.set_overrides({});
  EXPECT_EQ(w.pair(ma, ma).friction, 0.5);
}

TEST(PhaseOverrides, ABadOverrideIsRefused) {
  World w;
  const Index s = w.model.add_sphere_shape(1e-3);
  w.add_body(s, 0, 1.0, Vec3::Zero());
  w.step(1e-6);
  PhaseOverrides o;
  o.friction = {{7, 0.1}};
  EXPECT_THROW(w.set_overrides(o), InputError);
}

TEST(PhaseOverrides, SlidingSphereFeelsTheOverriddenFriction) {
  // A sphere on a plane tilted by t = 30 degrees under an overridden gravity
  // g = 10 m/s^2. With mu < (2/7) tan t it slides and spins up: its centre
  // accelerates at a = g (sin t - mu cos t) (frictionless: g sin t). The
  // Model's friction, 0.4, would make it roll (a = (5/7) g sin t).
  const double t = 30.0 * M_PI / 180.0, g = 10.0;
  const auto acceleration = [&](double mu_override) {
    World w;
    Material m;
    m.friction = 0.4;
    const Index mat = w.model.add_material(m);
    const Index s = w.model.add_sphere_shape(1e-3);
    const Vec3 n(-std::sin(t), 0, std::cos(t));  // plane normal
    w.add_plane(Vec3::Zero(), n, mat, "slope");
    w.add_body(s, mat, 1.0, n * (1e-3 - 1e-8));
    PhaseOverrides o;
    o.gravity = Vec3(0, 0, -g);
    o.friction = {{mat, mu_override}};
    w.set_overrides(o);
    const double dt = 1e-7;
    const int steps = 20000;
    for (int i = 0; i < steps; ++i) w.step(dt);
    const Vec3 down_slope(-std::cos(t), 0, -std::sin(t));
    return w.state.bodies[0].v.dot(down_slope) / (steps * dt);
  };
  EXPECT_NEAR(acceleration(0.0), g * std::sin(t), 0.03 * g * std::sin(t));
  const double mu = 0.1;
  EXPECT_NEAR(acceleration(mu), g * (std::sin(t) - mu * std::cos(t)), 0.03 * g * std::sin(t));
}
