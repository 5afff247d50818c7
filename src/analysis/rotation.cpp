// Rotation angles (derivation in rotation.h).
#include "analysis/rotation.h"

#include "analysis/preconditions.h"

#include <cmath>
#include <limits>

namespace grainlab::analysis {

double rotation_angle(const Quat& q) {
  return 2.0 * std::atan2(q.vec().norm(), std::abs(q.w()));
}

double relative_rotation_angle(const Quat& q_now, const Quat& q_ref) {
  // conjugate() is the inverse of a unit quaternion; for a non-unit q_ref it
  // differs from the inverse by a positive factor, which atan2 ignores.
  return rotation_angle(q_now * q_ref.conjugate());
}

std::vector<double> rotation_angles(const State& now, const State& ref) {
  check_same_bodies(now, ref, "rotation_angles");
  std::vector<double> theta(now.bodies.size());
  for (std::size_t i = 0; i < theta.size(); ++i)
    theta[i] = relative_rotation_angle(now.bodies[i].q, ref.bodies[i].q);
  return theta;
}

double mean_rotation_angle(const State& now, const State& ref, const GrainMask* mask) {
  check_same_bodies(now, ref, "mean_rotation_angle");
  check_mask(mask, now.bodies.size(), "mean_rotation_angle");
  double sum = 0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < now.bodies.size(); ++i) {
    if (mask && !(*mask)[i]) continue;
    sum += relative_rotation_angle(now.bodies[i].q, ref.bodies[i].q);
    ++n;
  }
  return n ? sum / static_cast<double>(n) : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace grainlab::analysis
