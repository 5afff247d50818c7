// The PI stress servo (derivation in stress_servo.h).
#include "lab/stress_servo.h"

#include <algorithm>

namespace grainlab {

void StressServo::control(World& w, double dt) {
  const auto ours = [&](Index wall) { return wall == walls_[0] || (count_ == 2 && wall == walls_[1]); };
  double k_walls = 0;
  for (const Contact& c : w.state.wall_contacts)
    if (ours(c.a) && in_contact(c) && c.geo.depth > 0)
      k_walls += w.model.law->tangent_stiffness(c.normal_force, c.geo.depth);
  double outward_speed = -speed_limit_;  // not touching yet: come in at the limit
  if (k_walls > 0) {
    const double gain = alpha_ * area_ / (k_walls * dt);
    const double error = stress(w) - target_;
    const double v = gain * (error + integral_);
    outward_speed = std::clamp(v, -speed_limit_, speed_limit_);
    // Integral action only while the walls are free to follow (no wind-up at the clamp).
    if (outward_speed == v) integral_ += alpha_ / 10 * error;
  } else {
    integral_ = 0;
  }
  for (int i = 0; i < count_; ++i) w.state.walls[walls_[i]].v[axis_] = -inward_ * outward_speed;
}

}  // namespace grainlab
