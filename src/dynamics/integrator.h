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
//
// Spheres four at a time (turn_spheres). A sphere's orientation enters no
// force, only the output, yet its update (the series, a quaternion product,
// a square root and a division) was a tenth of a bead step. Four spheres'
// updates share the lanes of one register, and the product p = r q0 is
// normalised by one Newton step for 1/|p|: with |p|^2 = 1 + e,
//     p' = p (3 - |p|^2) / 2,   |p'|^2 = (1 + e)(1 - e/2)^2 = 1 - 3e^2/4 + e^3/4,
// and e is a few ulps (q0 and r are unit to rounding), so p' is unit to
// rounding with no square root or division. A lane with |phi| >= 0.1 or
// |p|^2 off 1 by more than 1e-6 (an orientation set by hand) takes the
// scalar path. Angular velocities are updated as before, bit for bit.
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

// A sphere's angular velocity w after dt under world torque `torque`
// (L = I w, no gyroscopic term); inv_inertia its 1/I.
inline void spin_sphere(Vec3& w, const Vec3& torque, double inv_inertia, double dt) {
  w += inv_inertia * dt * torque;
}

// A sphere's orientation q turned by the rotation vector phi = w dt, one at
// a time (turn_spheres below: four).
inline void turn_sphere(Quat& q, const Vec3& phi) { q = (rotation_quaternion(phi) * q).normalized(); }

// Advances orientation q and world angular velocity w by dt under world torque
// `torque`, for principal moments `inertia` (and their inverses); a sphere
// takes spin_sphere and turn_sphere (or turn_spheres) instead.
inline void integrate_rotation(Quat& q, Vec3& w, const Vec3& torque, const Vec3& inertia,
                               const Vec3& inv_inertia, double dt) {
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

// Four spheres' orientations q[l] turned by the rotation vectors phi[l] (w dt
// after spin_sphere), four lanes at a time (see the top): turn_sphere's
// rotation, normalised without a square root.
inline void turn_spheres(Quat* const q[4], const Vec3 phi[4]) {
  using Lanes = double __attribute__((vector_size(32)));
  Lanes px, py, pz, qw, qx, qy, qz;
  for (int l = 0; l < 4; ++l) {
    px[l] = phi[l].x(), py[l] = phi[l].y(), pz[l] = phi[l].z();
    qw[l] = q[l]->w(), qx[l] = q[l]->x(), qy[l] = q[l]->y(), qz[l] = q[l]->z();
  }
  const Lanes a2 = px * px + py * py + pz * pz;
  const Lanes x2 = 0.25 * a2;
  const Lanes c = 1 - x2 * 0.5 * (1 - x2 * (1.0 / 12) * (1 - x2 * (1.0 / 30) * (1 - x2 * (1.0 / 56))));
  const Lanes h = 0.5 * (1 - x2 * (1.0 / 6) * (1 - x2 * (1.0 / 20) * (1 - x2 * (1.0 / 42) * (1 - x2 * (1.0 / 72)))));
  const Lanes rx = h * px, ry = h * py, rz = h * pz;  // r = (c, h phi)
  const Lanes w = c * qw - rx * qx - ry * qy - rz * qz;
  const Lanes x = c * qx + rx * qw + ry * qz - rz * qy;
  const Lanes y = c * qy + ry * qw + rz * qx - rx * qz;
  const Lanes z = c * qz + rz * qw + rx * qy - ry * qx;
  const Lanes n2 = w * w + x * x + y * y + z * z;
  const Lanes newton = 0.5 * (3 - n2);
  for (int l = 0; l < 4; ++l) {
    if (a2[l] < 1e-2 && std::abs(n2[l] - 1) < 1e-6) {
      *q[l] = Quat(w[l] * newton[l], x[l] * newton[l], y[l] * newton[l], z[l] * newton[l]);
    } else {
      turn_sphere(*q[l], phi[l]);
    }
  }
}

}  // namespace grainlab
