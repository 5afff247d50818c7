// Kanatani's density of contact normals (paper Eqs. 23-25, corrected).
//
// Seek a density on the unit sphere, f(n) >= 0 in good cases, with
//     int f dOmega = 1,   int n_i n_j f dOmega = phi_ij,   int n_i n_j n_k n_l f dOmega = phi_ijkl,
// of the form f(n) = (1/4pi) (1 + D_ij n_i n_j + D_ijkl n_i n_j n_k n_l) with
// D_ij and D_ijkl fully symmetric and traceless.
//
// Sphere moments: the integral over the sphere of a product of 2p components
// of n is 4pi / (1 3 5 ... (2p+1)) times the sum, over the (2p-1)!! ways of
// pairing its indices, of the products of Kronecker deltas d:
//     int n_i n_j = (4pi/3) d_ij,  int n_i n_j n_k n_l = (4pi/15)(d_ij d_kl + d_ik d_jl + d_il d_jk),
//     six n's: (4pi/105) x (15 pairings),  eight n's: (4pi/945) x (105 pairings).
// A traceless tensor contracted with a pairing that joins two of its own
// indices gives 0. Hence:
//  * Zeroth moment: the D terms vanish (every pairing of n_i n_j D_ij or of
//    D_ijkl n^4 joins two D indices): int f = 1 for any D. The 1/(4pi) is the
//    full sphere's area; the paper's 1/(2pi) would normalise over a hemisphere
//    only, but normals are sign-free and f(n) = f(-n), so grainlab counts the
//    whole sphere.
//  * Second moment: (1/4pi)[(4pi/3) d_ij + (4pi/15) 2 D_ij + 0] (D_ijkl: every
//    pairing of 6 indices with i, j against four D indices joins two of them),
//    so phi_ij = d_ij/3 + (2/15) D_ij, i.e.
//        D_ij = (15/2) (phi_ij - d_ij/3)       (the paper prints 2/15: inverted).
//  * Fourth moment: constant term (1/5) S(dd) (3 pairings: 3 S(dd)/15); D_mn
//    term: of the 15 pairings of ijklmn, 12 pair m and n with two of ijkl and
//    the other two together, giving 12 S(d D)/105 = (4/35) S(d D); D_mnpq term:
//    only the 4! = 24 pairings that match mnpq one-to-one with ijkl survive,
//    giving 24 D_ijkl / 945 = (8/315) D_ijkl. With D_ij above,
//        phi_ijkl = -(3/35) S(dd) + (6/7) S(d phi) + (8/315) D_ijkl,
//    so D_ijkl = (315/8) [phi_ijkl - (6/7) S(d phi) + (3/35) S(dd)]
//              = (315/8) dev(phi_ijkl)     (fabric.h; the paper prints 2/15).
// The second-order approximation (D_ijkl = 0) keeps the first two moments.
// f is in 1/sr; with few or strongly clustered normals it can go negative
// somewhere (a truncated series), which a plot should show honestly.
#pragma once

#include "analysis/fabric.h"
#include "analysis/tensor4.h"
#include "core/types.h"

namespace grainlab::analysis {

struct KanataniDensity {
  Mat3 D2 = Mat3::Zero();  // D_ij
  Tensor4 D4;              // D_ijkl (zero in the second-order approximation)

  // f(n) in 1/sr for a unit direction n.
  double operator()(const Vec3& n) const;
};

// The density whose moments reproduce `fabric` up to the fourth order (or the
// second order only, when fourth_order is false).
KanataniDensity kanatani_density(const FabricTensors& fabric, bool fourth_order = true);

}  // namespace grainlab::analysis
