// The PI stress servo (derivation in stress_servo.h).
#include "lab/stress_servo.h"

#include <algorithm>

namespace grainlab {

double servo_tangent_factor(ContactLaw law) { return law == ContactLaw::Hooke ? 1.0 : 1.5; }

void StressServo::control(World& w, double dt) {
  WallState& cap = w.state.walls[wall_];
  double k_cap = 0;
  const double tangent = servo_tangent_factor(w.model.law);
  for (const PairContact& pc : w.state.wall_pairs)
    if (pc.a == wall_ && in_contact(pc) && pc.geo.depth > 0) k_cap += tangent * pc.normal_force / pc.geo.depth;
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
