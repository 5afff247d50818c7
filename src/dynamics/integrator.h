// Time integration of one rigid body (paper Eqs. 3-6, with rotation done right).
//
// Translation, semi-implicit Euler:  v += (F/m) dt;  x += v dt.
//
// Rotation. The paper's Eq. 4 (w += M/I dt) and Eq. 6 (theta += w dt) hold
// only for spheres. For a body with principal moments J (body frame), world
// rotation R(q) and world angular momentum L = R J R^T w, Euler's equations
// dL/dt = M contain the gyroscopic term implicitly. We step
//     L1 = L0 + M dt                      (exact for the torque impulse)
//     q1 = exp(w_mid dt) q0,  w_mid = R_mid J^-1 R_mid^T L1
// where R_mid is the rotation half-way between q0 and q1 (implicit midpoint,
// solved by fixed-point iteration), and w1 = R(q1) J^-1 R(q1)^T L1. With no
// torque |L| is conserved exactly, and the symmetric midpoint rule keeps the
// energy error bounded (no drift) for a torque-free asymmetric body.
// exp(w dt) is the unit quaternion of a rotation by |w| dt about w/|w|.
#pragma once

#include "core/types.h"

#include <cmath>

namespace grainlab {

// Quaternion of the rotation vector phi (angle |phi| about phi/|phi|).
inline Quat rotation_quaternion(const Vec3& phi) {
  const double angle = phi.norm();
  if (angle < 1e-12) {
    // Series to second order keeps it smooth near zero.
    Quat q(1.0 - angle * angle / 8.0, 0.5 * phi.x(), 0.5 * phi.y(), 0.5 * phi.z());
    return q.normalized();
  }
  const double s = std::sin(0.5 * angle) / angle;
  return Quat(std::cos(0.5 * angle), s * phi.x(), s * phi.y(), s * phi.z());
}

// Advances orientation q and world angular velocity w by dt under world torque
// `torque`, for principal moments `inertia` (and their inverses).
inline void integrate_rotation(Quat& q, Vec3& w, const Vec3& torque, const Vec3& inertia,
                               const Vec3& inv_inertia, double dt, bool isotropic) {
  if (isotropic) {  // spheres: L = I w, no gyroscopic term
    w += inv_inertia.x() * dt * torque;
    q = (rotation_quaternion(w * dt) * q).normalized();
    return;
  }
  const Mat3 r0 = q.toRotationMatrix();
  const Vec3 l1 = r0 * inertia.cwiseProduct(r0.transpose() * w) + torque * dt;
  Quat q1 = q;
  Vec3 w_mid = r0 * inv_inertia.cwiseProduct(r0.transpose() * l1);
  for (int it = 0; it < 3; ++it) {
    q1 = (rotation_quaternion(w_mid * dt) * q).normalized();
    const Mat3 r_mid = q.slerp(0.5, q1).toRotationMatrix();
    w_mid = r_mid * inv_inertia.cwiseProduct(r_mid.transpose() * l1);
  }
  q1 = (rotation_quaternion(w_mid * dt) * q).normalized();
  const Mat3 r1 = q1.toRotationMatrix();
  w = r1 * inv_inertia.cwiseProduct(r1.transpose() * l1);
  q = q1;
}

}  // namespace grainlab
