// The contact law for one contact: the reference the World's four-lane loop
// (dynamics/contact_lanes.h) is checked against, contact by contact, in
// tests/dynamics/contact_lanes_test.cpp (the World itself only runs the
// lanes). The same formulas as contact_lanes.h's top comment.
#pragma once

#include "dynamics/contact_law.h"

#include <algorithm>
#include <cmath>

namespace grainlab {

// Kinematics of one touching contact at this step.
struct ContactKinematics {
  Vec3 normal;    // unit, from a to b
  double delta;   // overlap > 0
  Vec3 v_rel;     // velocity of b's material point minus a's, at the contact point
  double m_eff;   // kg
  double r_eff;   // m
  double gain = 1;  // multiplies the elastic normal force (a faceted contact's |G|, collision/soft_depth.h)
  double share = 1;  // multiplies the damping and the tangential spring (ContactResult::share)
};

// Force on body b (on a it is the opposite), updating the tangential spring
// `xi` (m): xi is first turned into the current tangent plane with its length
// kept, then advanced by v_t dt; if the trial force exceeds mu f_n the force is
// capped and xi set back to the value that gives exactly the capped force.
template <typename Law>
Vec3 contact_force(const PairCoefficients& p, const ContactKinematics& c, double dt, Vec3& xi,
                   double* normal_force_out = nullptr, LawCoefficients* coefficients_out = nullptr) {
  LawCoefficients k = Law::at(p, c.delta, c.r_eff, c.m_eff);
  k.c_n *= c.share, k.k_t *= c.share, k.c_t *= c.share;
  if (coefficients_out) *coefficients_out = k;
  const double v_n = c.v_rel.dot(c.normal);
  const Vec3 v_t = c.v_rel - v_n * c.normal;
  const double f_n = std::max(0.0, c.gain * k.k_n * c.delta - k.c_n * v_n);

  // Keep the spring in the tangent plane, with its length (one square root:
  // of the ratio of the squared lengths).
  const double len2 = xi.squaredNorm();
  if (len2 > 0) {
    xi -= xi.dot(c.normal) * c.normal;
    const double len_t2 = xi.squaredNorm();
    xi = len_t2 > 1e-300 ? Vec3(xi * std::sqrt(len2 / len_t2)) : Vec3::Zero();
  }
  xi += v_t * dt;

  Vec3 f_t = -k.k_t * xi - k.c_t * v_t;
  const double cap = p.friction * f_n;
  const double ft_len = f_t.norm();
  if (ft_len > cap) {
    f_t *= (ft_len > 0 ? cap / ft_len : 0.0);
    xi = k.k_t > 0 ? Vec3(-(f_t + k.c_t * v_t) / k.k_t) : Vec3::Zero();
  }
  if (normal_force_out) *normal_force_out = f_n;
  return f_n * c.normal + f_t;
}

}  // namespace grainlab
