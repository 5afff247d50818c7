// A fourth-order tensor in 3D, T_ijkl (i, j, k, l = 0..2), for the fabric
// tensor phi_ijkl and Kanatani's D_ijkl, with the few symmetric building
// blocks they need:
//   S(delta a)_ijkl = (1/6)(d_ij a_kl + d_ik a_jl + d_il a_jk + d_jk a_il + d_jl a_ik + d_kl a_ij)
//   S(delta delta)_ijkl = (1/3)(d_ij d_kl + d_ik d_jl + d_il d_jk)
// the full symmetrisations of delta (x) a (a symmetric) and of delta (x) delta.
#pragma once

#include "core/types.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace grainlab::analysis {

struct Tensor4 {
  std::array<double, 81> v{};  // row-major: ((i*3 + j)*3 + k)*3 + l

  double& operator()(int i, int j, int k, int l) { return v[((i * 3 + j) * 3 + k) * 3 + l]; }
  double operator()(int i, int j, int k, int l) const { return v[((i * 3 + j) * 3 + k) * 3 + l]; }

  // T_ijkl n_i n_j n_k n_l.
  double contract(const Vec3& n) const {
    double s = 0;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        for (int k = 0; k < 3; ++k)
          for (int l = 0; l < 3; ++l) s += (*this)(i, j, k, l) * n[i] * n[j] * n[k] * n[l];
    return s;
  }
  // The trace over the last pair, T_ijkk.
  Mat3 trace() const {
    Mat3 t = Mat3::Zero();
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        for (int k = 0; k < 3; ++k) t(i, j) += (*this)(i, j, k, k);
    return t;
  }
  // Largest |T_ijkl - U_ijkl|.
  double max_abs_diff(const Tensor4& u) const {
    double m = 0;
    for (std::size_t q = 0; q < v.size(); ++q) m = std::max(m, std::abs(v[q] - u.v[q]));
    return m;
  }
};

inline Tensor4 operator+(Tensor4 a, const Tensor4& b) {
  for (std::size_t q = 0; q < a.v.size(); ++q) a.v[q] += b.v[q];
  return a;
}
inline Tensor4 operator*(double s, Tensor4 a) {
  for (double& x : a.v) x *= s;
  return a;
}

// S(delta a), for symmetric a.
inline Tensor4 sym_delta_outer(const Mat3& a) {
  const auto d = [](int i, int j) { return i == j ? 1.0 : 0.0; };
  Tensor4 t;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l)
          t(i, j, k, l) = (d(i, j) * a(k, l) + d(i, k) * a(j, l) + d(i, l) * a(j, k) +
                           d(j, k) * a(i, l) + d(j, l) * a(i, k) + d(k, l) * a(i, j)) / 6.0;
  return t;
}

// S(delta delta).
inline Tensor4 sym_delta_delta() {
  const auto d = [](int i, int j) { return i == j ? 1.0 : 0.0; };
  Tensor4 t;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l) t(i, j, k, l) = (d(i, j) * d(k, l) + d(i, k) * d(j, l) + d(i, l) * d(j, k)) / 3.0;
  return t;
}

}  // namespace grainlab::analysis
