// A stress servo: a proportional-integral controller that moves a wall (or a
// group of walls moving as one: the two slabs of one side of the box) along
// one axis until the stress they carry is the target. The cap moves along z
// and pushes down (inward -z); a side wall along x or y.
//
// v_out = G (e + I) along the outward axis, e = sigma - sigma_target, I <- I + beta e each step, with
// G = alpha A / (k_w dt), where A is the loaded area and k_w the summed
// tangent stiffness d f / d delta of the wall's contacts, as the contact law
// gives it (ContactLaw::tangent_stiffness: 1.5 f / delta for Hertz, f / delta
// for Hooke). If the
// specimen were a spring k_w, the stress would change by -alpha (e + I) per
// step: alpha = 0.05 (the default) removes an error in about 1/alpha steps,
// slowly enough for the stress to cross the specimen; the triaxial test's
// side walls, which measure their own contacts, use 0.15 (lab/triaxial.h
// has the measurements). A purely proportional servo following
// a dilating specimen at speed u lags by e = u k_w dt / (alpha A), a few per
// cent in shear; the integral term (beta = alpha / 10, overdamped:
// beta < alpha / 4) removes that lag. The wall never moves faster than the
// speed limit (the speed is clamped, and the integral does not wind up while
// it is). While the wall touches nothing it comes down at the limit.
#pragma once

#include <array>

#include "core/bytes.h"
#include "dynamics/world.h"

namespace grainlab {

class StressServo {
 public:
  // Drives cap wall `wall` (its force.z / area is the stress, compressive
  // positive for a downward-facing cap) towards target (Pa), at most
  // speed_limit (m/s).
  StressServo(Index wall, double area, double target, double speed_limit)
      : StressServo({wall, wall}, 1, 2, -1.0, area, target, speed_limit) {}
  // Drives the first `count` (1 or 2) of `walls` as one along `axis` (0, 1,
  // 2), pushing the specimen towards `inward` (+1 or -1) on that axis.
  // alpha: the proportional gain (kAlpha unless given); the integral's beta = alpha / 10.
  StressServo(std::array<Index, 2> walls, int count, int axis, double inward, double area, double target,
              double speed_limit, double alpha = kAlpha)
      : walls_(walls), count_(count), axis_(axis), inward_(inward), area_(area), target_(target),
        speed_limit_(speed_limit), alpha_(alpha) {}

  // One control step: sets the walls' velocity along the axis from the forces of this step.
  void control(World& w, double dt);
  // The target stress (Pa).
  double target() const { return target_; }
  // The stress the walls carry now (Pa): compressive positive.
  double stress(const World& w) const {
    double f = 0;
    for (int i = 0; i < count_; ++i) f -= inward_ * w.state.walls[walls_[i]].force[axis_];
    return f / area_;
  }
  // The loaded area changes with the specimen (a side wall: its width times the height).
  void set_area(double area) { area_ = area; }
  // The integral term (Pa).
  double integral() const { return integral_; }

  // The controller's own state (the integral), little-endian.
  void save(ByteWriter& out) const { out.f64(integral_); }
  void load(ByteReader& in) { integral_ = in.f64(); }

  static constexpr double kAlpha = 0.05;  // the default gain; beta = alpha / 10: integral time 200 steps

 private:
  std::array<Index, 2> walls_;
  int count_, axis_;
  double inward_;
  double area_, target_, speed_limit_;
  double alpha_;  // the proportional gain; the integral's is alpha_ / 10
  double integral_ = 0;  // Pa
};

}  // namespace grainlab
