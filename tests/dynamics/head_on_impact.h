// A head-on impact of two equal spheres, shared by the contact laws' analytic
// impact tests: no gravity, the spheres start 1e-3 radius apart closing at
// relative speed v; the step dt is the caller's. Duration counts the steps
// with a contact; restitution is the separation speed over v.
#pragma once

#include "dynamics/world.h"

namespace grainlab::testing_support {

struct Impact {
  double duration = 0;     // s
  double restitution = 0;  // rebound / approach speed
};

inline Impact head_on_impact(ContactLaw law, const Material& mat, double radius, double v, double dt) {
  World w;
  w.model.law = law;
  w.model.gravity = Vec3::Zero();
  const Index m = w.model.add_material(mat);
  const Index s = w.model.add_sphere_shape(radius);
  const double gap = 1e-3 * radius;
  w.add_body(s, m, 1.0, Vec3(-radius - gap, 0, 0), Quat::Identity(), Vec3(0.5 * v, 0, 0));
  w.add_body(s, m, 1.0, Vec3(radius + gap, 0, 0), Quat::Identity(), Vec3(-0.5 * v, 0, 0));
  bool started = false;
  int touching_steps = 0;
  for (int i = 0; i < 100000; ++i) {
    w.step(dt);
    if (w.contact_count() > 0) {
      started = true;
      ++touching_steps;
    } else if (started) {
      break;
    }
  }
  return {touching_steps * dt, (w.state.bodies[1].v.x() - w.state.bodies[0].v.x()) / v};
}

}  // namespace grainlab::testing_support
