// Contact-law evaluators: each reduces a law to the four coefficients
// K_n, C_n, K_t, C_t at the current overlap (derivations in material.h), and
// one shared routine applies them with the tangential spring and Coulomb cap.
#pragma once

#include "core/types.h"
#include "dynamics/material.h"

#include <cmath>

namespace grainlab {

struct LawCoefficients {
  double k_n, c_n, k_t, c_t;
};

struct HookeLaw {
  static LawCoefficients at(const PairCoefficients& p, double /*delta*/, double /*r_eff*/,
                            double m_eff) {
    return {p.k_n, p.gamma_n * m_eff, p.k_t, p.gamma_t * m_eff};
  }
};

struct HertzUserLaw {
  static LawCoefficients at(const PairCoefficients& p, double delta, double r_eff, double m_eff) {
    const double s = std::sqrt(r_eff * delta);
    return {p.k_n * s, p.gamma_n * m_eff * s, p.k_t * s, p.gamma_t * m_eff * s};
  }
};

struct HertzMaterialLaw {
  static LawCoefficients at(const PairCoefficients& p, double delta, double r_eff, double m_eff) {
    constexpr double two_sqrt_5_6 = 1.8257418583505538;  // 2 sqrt(5/6)
    const double s = std::sqrt(r_eff * delta);
    const double s_n = 2.0 * p.k_n * s;  // k_n holds E*
    const double s_t = 8.0 * p.k_t * s;  // k_t holds G*
    return {(2.0 / 3.0) * s_n, two_sqrt_5_6 * p.gamma_n * std::sqrt(s_n * m_eff), s_t,
            two_sqrt_5_6 * p.gamma_t * std::sqrt(s_t * m_eff)};
  }
};

// Kinematics of one touching contact at this step.
struct ContactKinematics {
  Vec3 normal;    // unit, from a to b
  double delta;   // overlap > 0
  Vec3 v_rel;     // velocity of b's material point minus a's, at the contact point
  double m_eff;   // kg
  double r_eff;   // m
};

// Force on body b (on a it is the opposite), updating the tangential spring
// `xi` (m): xi is first turned into the current tangent plane with its length
// kept, then advanced by v_t dt; if the trial force exceeds mu f_n the force is
// capped and xi set back to the value that gives exactly the capped force.
template <typename Law>
Vec3 contact_force(const PairCoefficients& p, const ContactKinematics& c, double dt, Vec3& xi,
                   double* normal_force_out = nullptr, LawCoefficients* coefficients_out = nullptr) {
  const LawCoefficients k = Law::at(p, c.delta, c.r_eff, c.m_eff);
  if (coefficients_out) *coefficients_out = k;
  const double v_n = c.v_rel.dot(c.normal);
  const Vec3 v_t = c.v_rel - v_n * c.normal;
  const double f_n = std::max(0.0, k.k_n * c.delta - k.c_n * v_n);

  // Keep the spring in the tangent plane, with its length.
  const double len = xi.norm();
  if (len > 0) {
    xi -= xi.dot(c.normal) * c.normal;
    const double len_t = xi.norm();
    xi = len_t > 1e-300 ? Vec3(xi * (len / len_t)) : Vec3::Zero();
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

// Damping torque on b of an extended patch (a face lying on a wall).
// The normal damping -C_n v_n acts on every point of the patch; with v_n
// varying as (w x s).n over patch offsets s, the part beyond the force at the
// centroid is a torque -C_n D w with D = sum_i w_i (s_i x n)(s_i x n)^T, which
// for an isotropic patch of spread s2 = sum_i w_i |s_i|^2 is (s2/2)(I - n n^T).
// Without it a single contact point leaves the rocking of a flat face undamped.
inline Vec3 patch_damping_torque(double c_n, double spread, const Vec3& normal, const Vec3& w_rel) {
  return -c_n * 0.5 * spread * (w_rel - w_rel.dot(normal) * normal);
}

}  // namespace grainlab
