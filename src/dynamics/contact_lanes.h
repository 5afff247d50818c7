// The contact law for four contacts at once: the law's arithmetic (below)
// written on lanes of four doubles (GCC's vector
// extension: one AVX register with -march=x86-64-v3).
//
// Why. A contact's force is a chain of dependent square roots and divisions
// (sqrt(R* delta), sqrt(S_n m*), the spring's rescaling, |f_t| and the
// Coulomb cap), some 150 cycles of latency for a few dozen instructions; one
// contact after another, the processor waits on that chain (session 19:
// taking two square roots out of it changed nothing measurable). Four
// contacts in the lanes of one register share each wait.
//
// Step by step (the one-contact form's branches become selects):
//   C_n, K_t, C_t <- share C_n, share K_t, share C_t  (ContactResult::share);
//   f_n = max(0, gain K_n delta - C_n v_n),  v_n = v.n,  v_t = v - v_n n;
//   xi <- (xi - (xi.n) n) sqrt(|xi|^2 / |xi - (xi.n) n|^2)   (if xi != 0; 0 if
//         xi lies along n), then xi += v_t dt;
//   f_t = -K_t xi - C_t v_t; if |f_t| > mu f_n: f_t <- f_t (mu f_n / |f_t|) and
//         xi <- -(f_t + C_t v_t) / K_t (0 if K_t = 0).
// The roundings may differ from the one-contact form's by an ulp (FMA
// contraction is the compiler's in either); tests/dynamics/
// contact_lanes_test.cpp checks the two against each other on random
// contacts of every law (the one-contact form: contact_force_reference.h).
#pragma once

#include "dynamics/contact_law.h"

#include <cmath>

namespace grainlab {

inline constexpr int kLanes = 4;
using Lanes = double __attribute__((vector_size(8 * kLanes)));

// Lane-wise square root (an overload of contact_law.h's root()).
inline Lanes root(Lanes x) {
#if defined(__AVX__)
  return __builtin_ia32_sqrtpd256(x);
#else
  Lanes r;
  for (int l = 0; l < kLanes; ++l) r[l] = std::sqrt(x[l]);
  return r;
#endif
}

// Four contacts' kinematics (lane l for contact l) and their springs,
// updated in place.
struct ContactLanes {
  Lanes nx, ny, nz;  // unit normal, a to b
  Lanes delta;       // overlap (m)
  Lanes vx, vy, vz;  // velocity of b's material point minus a's (m/s)
  Lanes m_eff, r_eff, gain, share;
  Lanes xix, xiy, xiz;  // tangential spring (m), in and out
};

// What the law gives each lane: the force on b, f_n and the coefficients.
struct ForceLanes {
  Lanes fx, fy, fz, f_n;
  LawCoefficientsOf<Lanes> k;
};

template <typename Law>
ForceLanes contact_force_lanes(const PairCoefficientsOf<Lanes>& p, ContactLanes& c, double dt) {
  const Lanes zero{};
  ForceLanes out;
  LawCoefficientsOf<Lanes> k = Law::at(p, c.delta, c.r_eff, c.m_eff);
  k.c_n *= c.share, k.k_t *= c.share, k.c_t *= c.share;  // exact for share 1
  out.k = k;
  const Lanes v_n = c.vx * c.nx + c.vy * c.ny + c.vz * c.nz;
  const Lanes vtx = c.vx - v_n * c.nx, vty = c.vy - v_n * c.ny, vtz = c.vz - v_n * c.nz;
  const Lanes trial_n = c.gain * k.k_n * c.delta - k.c_n * v_n;
  const Lanes f_n = trial_n > 0.0 ? trial_n : zero;  // as std::max(0.0, x): NaN and -0 give +0

  // Keep the spring in the tangent plane, with its length.
  const Lanes len2 = c.xix * c.xix + c.xiy * c.xiy + c.xiz * c.xiz;
  const Lanes along = c.xix * c.nx + c.xiy * c.ny + c.xiz * c.nz;
  const Lanes px = c.xix - along * c.nx, py = c.xiy - along * c.ny, pz = c.xiz - along * c.nz;
  const Lanes len_t2 = px * px + py * py + pz * pz;
  const Lanes scale = len_t2 > 1e-300 ? root(len2 / len_t2) : zero;
  const auto turn = len2 > 0.0;
  Lanes xix = turn ? px * scale : c.xix, xiy = turn ? py * scale : c.xiy, xiz = turn ? pz * scale : c.xiz;
  xix += vtx * dt, xiy += vty * dt, xiz += vtz * dt;

  Lanes ftx = -k.k_t * xix - k.c_t * vtx, fty = -k.k_t * xiy - k.c_t * vty, ftz = -k.k_t * xiz - k.c_t * vtz;
  const Lanes cap = p.friction * f_n;
  const Lanes ft_len = root(ftx * ftx + fty * fty + ftz * ftz);
  const auto slide = ft_len > cap;
  bool any_slides = false;
  for (int l = 0; l < kLanes; ++l) any_slides |= slide[l] != 0;
  if (any_slides) {
    const Lanes ratio = slide ? (ft_len > 0.0 ? cap / ft_len : zero) : zero + 1.0;
    ftx *= ratio, fty *= ratio, ftz *= ratio;
    const auto springy = k.k_t > 0.0;
    xix = slide ? (springy ? -(ftx + k.c_t * vtx) / k.k_t : zero) : xix;
    xiy = slide ? (springy ? -(fty + k.c_t * vty) / k.k_t : zero) : xiy;
    xiz = slide ? (springy ? -(ftz + k.c_t * vtz) / k.k_t : zero) : xiz;
  }
  c.xix = xix, c.xiy = xiy, c.xiz = xiz;
  out.fx = f_n * c.nx + ftx, out.fy = f_n * c.ny + fty, out.fz = f_n * c.nz + ftz;
  out.f_n = f_n;
  return out;
}

}  // namespace grainlab
