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
// exp(w dt) is the unit quaternion of a rotation by |w| dt about w/|w|:
// (cos x, (sin x / |phi|) phi) with x = |phi|/2. A DEM step turns a grain by
// far less than 0.1 rad, where the Taylor series to x^8,
//   sin x / x = 1 - x^2/6 (1 - x^2/20 (1 - x^2/42 (1 - x^2/72))),
//   cos x     = 1 - x^2/2 (1 - x^2/12 (1 - x^2/30 (1 - x^2/56))),
// is exact to rounding (the first term left out, x^10/11! or x^10/10!, is
// below 1e-20 for x < 0.05) and needs no sin, cos or square root. The
// rotation half-way between q0 and q1 (slerp at 1/2) is (q0 + q1)/|q0 + q1|,
// with q1's sign taken on q0's side: no acos either.
#pragma once

#include "core/types.h"

#include <cmath>

namespace grainlab {

// Quaternion of the rotation vector phi (angle |phi| about phi/|phi|).
inline Quat rotation_quaternion(const Vec3& phi) {
  const double a2 = phi.squaredNorm();
  if (a2 < 1e-2) {  // |phi| < 0.1: the series above
    // Products with the rounded reciprocals, not divisions: the same value to
    // within an ulp, at a fraction of the cost (a body per step each).
    const double x2 = 0.25 * a2;
    const double c = 1 - x2 * 0.5 * (1 - x2 * (1.0 / 12) * (1 - x2 * (1.0 / 30) * (1 - x2 * (1.0 / 56))));
    const double s = 0.5 * (1 - x2 * (1.0 / 6) * (1 - x2 * (1.0 / 20) * (1 - x2 * (1.0 / 42) * (1 - x2 * (1.0 / 72)))));
    return Quat(c, s * phi.x(), s * phi.y(), s * phi.z());
  }
  const double angle = std::sqrt(a2);
  const double s = std::sin(0.5 * angle) / angle;
  return Quat(std::cos(0.5 * angle), s * phi.x(), s * phi.y(), s * phi.z());
}

// The rotation half-way between unit quaternions q0 and q1 (slerp at 1/2).
inline Quat halfway(const Quat& q0, const Quat& q1) {
  const double sign = q0.coeffs().dot(q1.coeffs()) < 0 ? -1.0 : 1.0;
  return Quat(q0.coeffs() + sign * q1.coeffs()).normalized();
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
    const Mat3 r_mid = halfway(q, q1).toRotationMatrix();
    w_mid = r_mid * inv_inertia.cwiseProduct(r_mid.transpose() * l1);
  }
  q1 = (rotation_quaternion(w_mid * dt) * q).normalized();
  const Mat3 r1 = q1.toRotationMatrix();
  w = r1 * inv_inertia.cwiseProduct(r1.transpose() * l1);
  q = q1;
}

}  // namespace grainlab
