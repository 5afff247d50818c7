// Spherical harmonics (see spherical_harmonics.h).
//
// Convention (Garboczi's files, scipy's sph_harm): with x = cos(theta),
// s = sin(theta) and P_n^m the associated Legendre function WITHOUT the
// Condon-Shortley phase (P_m^m = (2m-1)!! s^m > 0),
//   Y_nm = (-1)^m N_nm P_n^m(x) e^{i m phi},  N_nm = sqrt((2n+1)/(4 pi) (n-m)!/(n+m)!),
//   Y_{n,-m} = (-1)^m conj(Y_nm),
// orthonormal over the sphere.
//
// Evaluation. The factorials overflow and P_n^m spans hundreds of orders of
// magnitude, so the normalised functions Pb_n^m = N_nm P_n^m are computed
// directly by the recursions that follow from the classical ones divided by
// N_nm (each stays of order one; Holmes & Featherstone, J. Geodesy 76 (2002)):
//   Pb_0^0     = 1 / sqrt(4 pi)
//   Pb_m^m     = sqrt((2m+1) / (2m)) s Pb_{m-1}^{m-1}
//                  [P_m^m = (2m-1) s P_{m-1}^{m-1}; N_mm / N_{m-1,m-1} = sqrt((2m+1)/(2m-1) / (2m (2m-1)))]
//   Pb_{m+1}^m = sqrt(2m+3) x Pb_m^m
//   Pb_n^m     = a_nm x Pb_{n-1}^m - b_nm Pb_{n-2}^m,   n >= m + 2,
//                  a_nm = sqrt((4n^2 - 1) / (n^2 - m^2)),
//                  b_nm = sqrt((2n+1) ((n-1)^2 - m^2) / ((2n-3) (n^2 - m^2)))
//                  [from (n-m) P_n^m = (2n-1) x P_{n-1}^m - (n+m-1) P_{n-2}^m].
// The recursion in n at fixed m is the stable direction; e^{i m phi} comes
// from repeated multiplication by e^{i phi}. At degree 30 Y_nm agrees with
// the closed forms to about 1e-14 (tests/geometry/spherical_harmonics_test.cpp).
//
// A real r has a_{n,-m} = (-1)^m conj(a_nm); the sum is evaluated in full and
// its real part taken, so a file that breaks the symmetry still gives the
// real part of its own sum:
//   r = Re sum_n [ a_n0 Y_n0 + sum_{m>0} (a_nm Y_nm + a_{n,-m} (-1)^m conj(Y_nm)) ].
//
// Projection. Y_nm conj(Y_n'm') times a function of degree <= band is a
// polynomial of degree <= 2 band in x times e^{i k phi}, |k| <= 2 band:
// band + 1 Gauss-Legendre nodes in x integrate the polynomial exactly and
// 2 band + 1 equal steps in phi the trigonometric part, so the sum of
// w_i f(u_i) conj(Y_nm(u_i)) is the exact coefficient of such an f.
#include "geometry/spherical_harmonics.h"

#include "core/error.h"

#include <cmath>
#include <numbers>

namespace grainlab {
namespace {

// Gauss-Legendre nodes and weights on [-1, 1] (Newton on P_n from the
// Chebyshev-like first guess; converges to machine precision in a few steps).
void gauss_legendre(int n, std::vector<double>& x, std::vector<double>& w) {
  x.assign(static_cast<std::size_t>(n), 0);
  w.assign(static_cast<std::size_t>(n), 0);
  for (int i = 0; i < n; ++i) {
    double z = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5));
    double dp = 1;
    for (int iter = 0; iter < 100; ++iter) {
      double p0 = 1, p1 = z;  // P_0, P_1
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (z * p1 - p0) / (z * z - 1);  // P_n' from P_n = p1, P_{n-1} = p0 (n >= 1)
      const double step = p1 / dp;
      z -= step;
      if (std::abs(step) < 1e-16) break;
    }
    x[i] = z;
    w[i] = 2 / ((1 - z * z) * dp * dp);
  }
}

// The recursions' factors a_nm, b_nm (at sh_index(n, m)) and sqrt((2m+1)/(2m)),
// computed once per thread for the largest degree asked so far.
struct RecursionFactors {
  int degree = -1;
  std::vector<double> a, b, diagonal;

  void ensure(int d) {
    if (d <= degree) return;
    degree = d;
    a.assign(static_cast<std::size_t>(sh_count(d)), 0);
    b.assign(a.size(), 0);
    diagonal.assign(static_cast<std::size_t>(d + 1), 0);
    for (int m = 1; m <= d; ++m) diagonal[m] = std::sqrt((2.0 * m + 1) / (2.0 * m));
    for (int m = 0; m <= d; ++m) {
      for (int n = m + 2; n <= d; ++n) {
        const double nn = static_cast<double>(n) * n - static_cast<double>(m) * m;
        a[static_cast<std::size_t>(sh_index(n, m))] = std::sqrt((4.0 * n * n - 1) / nn);
        b[static_cast<std::size_t>(sh_index(n, m))] =
            std::sqrt((2.0 * n + 1) * ((n - 1.0) * (n - 1.0) - m * m) / ((2.0 * n - 3) * nn));
      }
    }
  }
};

}  // namespace

double polar_angle(const Vec3& u) { return std::atan2(std::hypot(u.x(), u.y()), u.z()); }
double azimuth(const Vec3& u) { return std::atan2(u.y(), u.x()); }
Vec3 direction_of(double theta, double phi) {
  return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

void sh_basis(int degree, double theta, double phi, std::vector<std::complex<double>>& y) {
  y.resize(static_cast<std::size_t>(sh_count(degree)));
  thread_local RecursionFactors f;
  f.ensure(degree);
  const double x = std::cos(theta), s = std::sin(theta);
  const std::complex<double> step = std::polar(1.0, phi);
  std::complex<double> e = 1;  // e^{i m phi}
  double pmm = 1 / std::sqrt(4 * std::numbers::pi);
  for (int m = 0; m <= degree; ++m) {
    if (m > 0) {
      pmm *= f.diagonal[m] * s;
      e *= step;
    }
    const std::complex<double> phase = (m % 2 ? -1.0 : 1.0) * e;
    double p2 = 0, p1 = pmm;  // Pb_{n-2}^m, Pb_{n-1}^m
    y[static_cast<std::size_t>(sh_index(m, m))] = pmm * phase;
    if (m + 1 <= degree) {
      const double p = std::sqrt(2.0 * m + 3) * x * pmm;
      y[static_cast<std::size_t>(sh_index(m + 1, m))] = p * phase;
      p2 = pmm;
      p1 = p;
    }
    for (int n = m + 2; n <= degree; ++n) {
      const auto i = static_cast<std::size_t>(sh_index(n, m));
      const double p = f.a[i] * x * p1 - f.b[i] * p2;
      y[i] = p * phase;
      p2 = p1;
      p1 = p;
    }
  }
}

double sh_radius(const ShCoefficients& c, const Vec3& u) {
  thread_local std::vector<std::complex<double>> y;
  sh_basis(c.degree, polar_angle(u), azimuth(u), y);
  double r = 0;
  for (int n = 0; n <= c.degree; ++n) {
    r += (c.at(n, 0) * y[static_cast<std::size_t>(sh_index(n, 0))]).real();
    for (int m = 1; m <= n; ++m) {
      const std::complex<double> ynm = y[static_cast<std::size_t>(sh_index(n, m))];
      r += (c.at(n, m) * ynm).real() + (m % 2 ? -1.0 : 1.0) * (c.at(n, -m) * std::conj(ynm)).real();
    }
  }
  return r;
}

SphereQuadrature sphere_quadrature(int band) {
  if (band < 0) input_error("sphere_quadrature: band must be >= 0, got {}", band);
  std::vector<double> x, w;
  gauss_legendre(band + 1, x, w);
  const int n_phi = 2 * band + 1;
  SphereQuadrature q;
  q.n_phi = n_phi;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double theta = std::acos(x[i]);
    q.thetas.push_back(theta);
    for (int j = 0; j < n_phi; ++j) {
      q.directions.push_back(direction_of(theta, 2 * std::numbers::pi * j / n_phi));
      q.weights.push_back(w[i] * 2 * std::numbers::pi / n_phi);
    }
  }
  return q;
}

std::vector<double> sh_radii(const ShCoefficients& c, const SphereQuadrature& q) {
  std::vector<double> r;
  r.reserve(q.directions.size());
  std::vector<std::complex<double>> y, sum(static_cast<std::size_t>(c.degree + 1));
  for (const double theta : q.thetas) {
    sh_basis(c.degree, theta, 0.0, y);  // Y_nm at phi = 0: real, (-1)^m Pb_n^m
    for (int m = 0; m <= c.degree; ++m) {
      std::complex<double> plus = 0, minus = 0;
      for (int n = m; n <= c.degree; ++n) {
        const double q_nm = y[static_cast<std::size_t>(sh_index(n, m))].real();
        plus += q_nm * c.at(n, m);
        minus += q_nm * c.at(n, -m);
      }
      // a_nm Y_nm + a_{n,-m} (-1)^m conj(Y_nm) = q_nm (a_nm e^{i m phi} + (-1)^m a_{n,-m} e^{-i m phi}),
      // whose real part is Re((a_nm + (-1)^m conj(a_{n,-m})) q_nm e^{i m phi}).
      sum[m] = m == 0 ? plus : plus + (m % 2 ? -1.0 : 1.0) * std::conj(minus);
    }
    for (int j = 0; j < q.n_phi; ++j) {
      const std::complex<double> step = std::polar(1.0, 2 * std::numbers::pi * j / q.n_phi);
      std::complex<double> e = 1;
      double value = 0;
      for (int m = 0; m <= c.degree; ++m) {
        value += (sum[m] * e).real();
        e *= step;
      }
      r.push_back(value);
    }
  }
  return r;
}

ShCoefficients sh_project(const SphereQuadrature& q, std::span<const double> values, int degree) {
  if (values.size() != q.directions.size()) {
    input_error("sh_project: {} values for {} quadrature directions", values.size(), q.directions.size());
  }
  ShCoefficients c(degree);
  std::vector<std::complex<double>> y;
  for (std::size_t i = 0; i < values.size(); ++i) {
    sh_basis(degree, polar_angle(q.directions[i]), azimuth(q.directions[i]), y);
    const double f = q.weights[i] * values[i];
    for (int n = 0; n <= degree; ++n) {
      for (int m = 0; m <= n; ++m) {
        const std::complex<double> ynm = y[static_cast<std::size_t>(sh_index(n, m))];
        c.at(n, m) += f * std::conj(ynm);
        // conj(Y_{n,-m}) = (-1)^m Y_nm
        if (m > 0) c.at(n, -m) += (m % 2 ? -1.0 : 1.0) * f * ynm;
      }
    }
  }
  return c;
}

std::vector<double> sh_degree_amplitudes(const ShCoefficients& c) {
  std::vector<double> out;
  const double a0 = std::abs(c.at(0, 0));
  for (int n = 0; n <= c.degree; ++n) {
    double sum = 0;
    for (int m = -n; m <= n; ++m) sum += std::norm(c.at(n, m));
    out.push_back(std::sqrt(sum) / a0);
  }
  return out;
}

}  // namespace grainlab
