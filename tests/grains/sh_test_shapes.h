// SH coefficients of analytic test shapes, computed by the tests themselves.
#pragma once

#include "core/rng.h"
#include "geometry/spherical_harmonics.h"

#include <cmath>

namespace grainlab::test {

// The ellipsoid x^2/a^2 + y^2/b^2 + z^2/c^2 = 1 about its centre,
// r(u) = 1 / sqrt(u_x^2/a^2 + u_y^2/b^2 + u_z^2/c^2), projected to `degree`
// with a quadrature of band 2 degree (its higher degrees fall off
// geometrically, so they barely alias).
inline ShCoefficients ellipsoid_coefficients(double a, double b, double c, int degree) {
  const SphereQuadrature q = sphere_quadrature(2 * degree);
  std::vector<double> r;
  for (const Vec3& u : q.directions) {
    r.push_back(1 / std::sqrt(u.x() * u.x() / (a * a) + u.y() * u.y() / (b * b) + u.z() * u.z() / (c * c)));
  }
  return sh_project(q, r, degree);
}

// A real, lumpy grain of the given degree (mean radius 1): a_{n,-m} =
// (-1)^m conj(a_nm), amplitudes falling as 0.12 / n. With `even_only` the odd
// degrees are zero: r(-u) = r(u), so the body is symmetric about the origin
// and its centroid is there.
inline ShCoefficients lumpy_grain(int degree, std::uint64_t seed = 7, bool even_only = false) {
  Rng rng(seed);
  ShCoefficients c(degree);
  c.at(0, 0) = std::sqrt(4 * 3.141592653589793);
  for (int n = 1; n <= degree; ++n) {
    for (int m = 0; m <= n; ++m) {
      if (even_only && n % 2) continue;
      c.at(n, m) = std::complex<double>(rng.uniform(-1, 1), m == 0 ? 0 : rng.uniform(-1, 1)) * (0.12 / n);
      if (m > 0) c.at(n, -m) = (m % 2 ? -1.0 : 1.0) * std::conj(c.at(n, m));
    }
  }
  return c;
}

}  // namespace grainlab::test
