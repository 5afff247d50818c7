// The PI stress servo (derivation in stress_servo.h).
#include "lab/stress_servo.h"

#include <algorithm>

namespace grainlab {

void StressServo::control(World& w, double dt) {
  WallState& cap = w.state.walls[wall_];
  double k_cap = 0;
  for (const Contact& c : w.state.wall_contacts)
    if (c.a == wall_ && in_contact(c) && c.geo.depth > 0)
      k_cap += w.model.law->tangent_stiffness(c.normal_force, c.geo.depth);
  if (k_cap <= 0) {
    cap.v.z() = -speed_limit_;  // not touching yet: come down
    integral_ = 0;
    return;
  }
  const double gain = kAlpha * area_ / (k_cap * dt);
  const double error = stress(w) - target_;
  const double v = gain * (error + integral_);
  cap.v.z() = std::clamp(v, -speed_limit_, speed_limit_);
  // Integral action only while the wall is free to follow (no wind-up at the clamp).
  if (cap.v.z() == v) integral_ += kBeta * error;
}

}  // namespace grainlab
