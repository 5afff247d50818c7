// A stress servo: a proportional-integral controller that moves one plane
// wall along its normal (here z) until the stress it carries is the target.
//
// v_z = G (e + I), e = sigma - sigma_target, I <- I + beta e each step, with
// G = alpha A / (k_w dt), where A is the loaded area and k_w the summed
// tangent stiffness d f / d delta of the wall's contacts, as the contact law
// gives it (ContactLaw::tangent_stiffness: 1.5 f / delta for Hertz, f / delta
// for Hooke). If the
// specimen were a spring k_w, the stress would change by -alpha (e + I) per
// step: alpha = 0.05 removes an error in about 1/alpha steps, slowly enough
// for the stress to cross the specimen. A purely proportional servo following
// a dilating specimen at speed u lags by e = u k_w dt / (alpha A), a few per
// cent in shear; the integral term (beta = alpha / 10, overdamped:
// beta < alpha / 4) removes that lag. The wall never moves faster than the
// speed limit (the speed is clamped, and the integral does not wind up while
// it is). While the wall touches nothing it comes down at the limit.
#pragma once

#include "core/bytes.h"
#include "dynamics/world.h"

namespace grainlab {

class StressServo {
 public:
  // Drives wall `wall` (its force.z / area is the stress, compressive
  // positive for a downward-facing cap) towards target (Pa), at most
  // speed_limit (m/s).
  StressServo(Index wall, double area, double target, double speed_limit)
      : wall_(wall), area_(area), target_(target), speed_limit_(speed_limit) {}

  // One control step: sets the wall's z velocity from the forces of this step.
  void control(World& w, double dt);
  // The target stress (Pa).
  double target() const { return target_; }
  // The stress the wall carries now (Pa).
  double stress(const World& w) const { return w.state.walls[wall_].force.z() / area_; }
  // The integral term (Pa).
  double integral() const { return integral_; }

  // The controller's own state (the integral), little-endian.
  void save(ByteWriter& out) const { out.f64(integral_); }
  void load(ByteReader& in) { integral_ = in.f64(); }

  static constexpr double kAlpha = 0.05;
  static constexpr double kBeta = 0.005;  // per step: integral time 200 steps (beta = alpha / 10)

 private:
  Index wall_;
  double area_, target_, speed_limit_;
  double integral_ = 0;  // Pa
};

}  // namespace grainlab
