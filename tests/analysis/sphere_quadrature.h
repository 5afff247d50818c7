// Product quadrature over the unit sphere for the analysis tests: Gauss-Legendre
// in mu = cos(theta) times the midpoint rule in the azimuth phi. With n_mu
// nodes it integrates polynomials of degree < 2 n_mu in mu exactly, and the
// azimuth rule with n_phi points is exact for trigonometric polynomials of
// degree < n_phi, so every polynomial in (n_x, n_y, n_z) of degree < min(2 n_mu, n_phi)
// comes out to rounding.
#pragma once

#include "core/types.h"

#include <cmath>
#include <numbers>
#include <vector>

namespace grainlab::testing_support {

struct SpherePoint {
  Vec3 n;
  double weight;  // sr; the weights sum to 4 pi
};

// Gauss-Legendre nodes and weights on [-1, 1] (Newton on P_n from the usual
// cosine guesses).
inline void gauss_legendre(int n, std::vector<double>& x, std::vector<double>& w) {
  x.assign(n, 0.0);
  w.assign(n, 0.0);
  for (int i = 0; i < n; ++i) {
    double z = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5));
    double dp = 0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1, p1 = z;  // P_0, P_1
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2.0 * k - 1) * z * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (z * p1 - p0) / (z * z - 1);  // P_n'
      const double dz = p1 / dp;
      z -= dz;
      if (std::abs(dz) < 1e-16) break;
    }
    x[i] = z;
    w[i] = 2.0 / ((1 - z * z) * dp * dp);
  }
}

inline std::vector<SpherePoint> sphere_quadrature(int n_mu, int n_phi) {
  std::vector<double> mu, wmu;
  gauss_legendre(n_mu, mu, wmu);
  std::vector<SpherePoint> pts;
  for (int i = 0; i < n_mu; ++i) {
    const double s = std::sqrt(1 - mu[i] * mu[i]);
    for (int j = 0; j < n_phi; ++j) {
      const double phi = 2 * std::numbers::pi * (j + 0.5) / n_phi;
      pts.push_back({Vec3(s * std::cos(phi), s * std::sin(phi), mu[i]), wmu[i] * 2 * std::numbers::pi / n_phi});
    }
  }
  return pts;
}

}  // namespace grainlab::testing_support
