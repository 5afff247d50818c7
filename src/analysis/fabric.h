// Fabric tensors of contact normals (paper Eqs. 27-29).
//
// For N_c unit contact normals n^m with weights w_m (1 by default),
//     phi_ij   = sum_m w_m n_i n_j / sum_m w_m            (Eq. 27)
//     phi_ijkl = sum_m w_m n_i n_j n_k n_l / sum_m w_m    (Eq. 28)
// Both are fully symmetric, and since |n| = 1 their traces are phi_ii = 1 and
// phi_ijkk = phi_ij. A contact normal has no sign (n and -n describe the same
// contact; grainlab's points from body a to body b, an arbitrary order): these
// tensors are of even order, so they are the same for n and -n.
//
// Deviatoric (traceless) parts:
//     D2_ij   = phi_ij - (1/3) tr(phi) delta_ij
//     D4_ijkl = phi_ijkl - (6/7) S(delta phi2)_ijkl + (3/35) tr(phi2) S(delta delta)_ijkl
// with phi2_ij = phi_ijkk and S(.) the full symmetrisation (tensor4.h). Check:
// the trace over k = l of S(delta a) is (delta tr a + 7 a)/6 and of S(delta delta)
// is (5/3) delta, so the trace of D4 is phi2 - (delta tr + 7 phi2)/7 + delta tr/7 = 0.
// Eq. 25 of the paper writes delta_ij phi_kl unsymmetrised, which is not
// traceless over every index pair; the symmetrised form is Kanatani's.
//
// Octahedral fabric factor (Eq. 29, Barreto and O'Sullivan), from the
// principal values phi_1 >= phi_2 >= phi_3:
//     Psi = (1/sqrt 2) [(phi_1-phi_2)^2 + (phi_1-phi_3)^2 + (phi_2-phi_3)^2]^(1/2).
// As sum_{a<b} (phi_a - phi_b)^2 = 3 sum_a phi_a^2 - (sum_a phi_a)^2 = 3 |D2|^2
// (Frobenius norm), Psi = sqrt(3/2) |D2|, the fabric analogue of the von Mises
// q: no eigenvalues needed. Isotropic fabric (phi = I/3) gives 0; all normals
// along one axis (phi = diag(0, 0, 1)) gives 1, the largest value a trace-one
// fabric tensor can have (|D2|^2 = sum phi_a^2 - 1/3 <= 2/3).
#pragma once

#include "analysis/grain_mask.h"
#include "analysis/tensor4.h"
#include "core/types.h"
#include "dynamics/state.h"

#include <cstddef>
#include <span>
#include <vector>

namespace grainlab::analysis {

// The unit normals of the grain-grain contacts (wall contacts are not part of
// the specimen's fabric). With a mask, the contacts of the grains in it, each
// once per grain of the mask it touches (the same counting as CN_S in
// coordination.h, so the list holds CN_S |S| normals).
std::vector<Vec3> contact_normals(const State& s, const GrainMask* mask = nullptr);

struct FabricTensors {
  Mat3 phi = Mat3::Zero();    // phi_ij (dimensionless, trace 1)
  Tensor4 phi4;               // phi_ijkl
  std::size_t count = 0;      // normals used
  double total_weight = 0;    // sum of their weights
};

// phi_ij and phi_ijkl of `normals` (normalised here; a zero vector throws),
// weighted by `weights` if given (one per normal, >= 0, not all zero). No
// normals: zero tensors and count 0.
FabricTensors fabric_tensors(std::span<const Vec3> normals, std::span<const double> weights = {});

// Traceless parts D2 and D4 (formulas above).
Mat3 deviatoric_part(const Mat3& phi);
Tensor4 deviatoric_part(const Tensor4& phi4);

// Principal values of a symmetric tensor, largest first, and their unit
// directions as the matching columns (a right-handed frame; each column's sign
// is otherwise arbitrary).
struct Principal {
  Vec3 values = Vec3::Zero();
  Mat3 directions = Mat3::Identity();
};
Principal principal(const Mat3& phi);

// Psi from principal values (Eq. 29), and from the tensor (sqrt(3/2) |D2|).
double octahedral_fabric_factor(const Vec3& principal_values);
double octahedral_fabric_factor(const Mat3& phi);

}  // namespace grainlab::analysis
