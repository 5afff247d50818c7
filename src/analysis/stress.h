// Love-Weber mean stress of a granular specimen from its contact forces.
//
// Sign: compression positive (the geomechanics convention of the paper's
// normal stress sigma_n = N / A). In the usual tension-positive convention
// sigma^t, for a grain p in static equilibrium under contact forces f^c
// (acting on p at points x^c) and its weight m g (through its centre x_p),
// the divergence theorem with div sigma + b = 0 gives
//     int_p sigma^t dV = sum_c f^c (x) x^c + m g (x) x_p = sum_c f^c (x) (x^c - x_p),
// the last step by force balance sum_c f^c + m g = 0: weight drops out.
// Summing over the grains of a specimen of volume V, sigma = -sigma^t:
//  * grain-grain contact, force F on b (Contact::force), -F on a:
//        F (x) (x^c - x_b) - F (x) (x^c - x_a) = -F (x) (x_b - x_a),
//    so it adds F (x) l with the branch vector l = x_b - x_a between the
//    centres (the contact point drops out);
//  * wall contact, force F on the grain b: it adds -F (x) (x^c - x_b), i.e.
//    the force the grain puts on the wall (-F) times the branch vector from
//    the grain's centre to the contact point (only the grain's half of the
//    contact lies inside V).
// So sigma_ij = (1/V) sum_c f_i^c l_j^c. Under compression F points along l
// and sigma_zz > 0. The identity is exact for grains at rest; moving grains
// add inertia terms it leaves out (fine for quasi-static tests, I << 1e-3).
// V is the caller's (the specimen's volume: box area times height, m^3).
//
// The sum is symmetric when each grain is also in moment balance; its
// antisymmetric part measures how far the sample is from it (and the patch
// damping torques, Contact::torque, which carry no force, are left out).
// The report gives the symmetric part and that asymmetry.
#pragma once

#include "core/types.h"
#include "dynamics/state.h"

namespace grainlab::analysis {

struct StressTensor {
  Mat3 sigma = Mat3::Zero();      // symmetric part (Pa), compression positive
  Mat3 raw = Mat3::Zero();        // sum before symmetrising (Pa)
  double asymmetry = 0;           // |raw - raw^T| / (2 |raw|) (Frobenius norms); 0 for no contacts
  double mean = 0;                // p = tr(sigma) / 3 (Pa)
  double deviatoric = 0;          // q = sqrt(3/2 s:s), s = sigma - p I (Pa)
};

// Mean stress over volume `volume` (m^3) from the contacts in `s` (grain-grain
// always; wall-grain unless include_walls is false).
StressTensor love_weber_stress(const State& s, double volume, bool include_walls = true);

}  // namespace grainlab::analysis
