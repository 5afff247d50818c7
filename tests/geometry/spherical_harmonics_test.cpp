// Spherical harmonics: Y_nm against closed forms and the C++ library's
// associated Legendre functions to degree 30, orthonormality under the
// quadrature, exact projection of a band-limited function, and the
// rotation invariance of the degree amplitudes.
#include "geometry/spherical_harmonics.h"

#include "core/rng.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace grainlab {
namespace {

constexpr double kPi = std::numbers::pi;

std::complex<double> y_of(int n, int m, double theta, double phi) {
  std::vector<std::complex<double>> y;
  sh_basis(n, theta, phi, y);
  if (m >= 0) return y[static_cast<std::size_t>(sh_index(n, m))];
  return (m % 2 ? -1.0 : 1.0) * std::conj(y[static_cast<std::size_t>(sh_index(n, -m))]);
}

TEST(SphericalHarmonics, LowDegreesMatchClosedForms) {
  for (double theta : {0.0, 0.3, 1.1, 2.0, kPi}) {
    for (double phi : {-2.5, 0.0, 0.7}) {
      const double x = std::cos(theta), s = std::sin(theta);
      const std::complex<double> e1 = std::polar(1.0, phi), e2 = std::polar(1.0, 2 * phi);
      EXPECT_NEAR(std::abs(y_of(0, 0, theta, phi) - 1 / std::sqrt(4 * kPi)), 0, 1e-15);
      EXPECT_NEAR(std::abs(y_of(1, 0, theta, phi) - std::sqrt(3 / (4 * kPi)) * x), 0, 1e-15);
      // scipy's sph_harm(1, 1, phi, theta) = -sqrt(3/(8 pi)) sin(theta) e^{i phi}
      EXPECT_NEAR(std::abs(y_of(1, 1, theta, phi) + std::sqrt(3 / (8 * kPi)) * s * e1), 0, 1e-15);
      EXPECT_NEAR(std::abs(y_of(1, -1, theta, phi) - std::sqrt(3 / (8 * kPi)) * s * std::conj(e1)), 0, 1e-15);
      EXPECT_NEAR(std::abs(y_of(2, 1, theta, phi) + std::sqrt(15 / (8 * kPi)) * s * x * e1), 0, 1e-15);
      EXPECT_NEAR(std::abs(y_of(2, 2, theta, phi) - 0.25 * std::sqrt(15 / (2 * kPi)) * s * s * e2), 0, 1e-15);
    }
  }
}

TEST(SphericalHarmonics, DegreeThirtyMatchesTheLibrarysLegendreFunctions) {
  // std::assoc_legendre has no Condon-Shortley phase, as the files' P_n^m.
  for (double theta : {0.05, 0.6, 1.4, 2.9}) {
    std::vector<std::complex<double>> y;
    sh_basis(30, theta, 0.4, y);
    for (int n = 0; n <= 30; ++n) {
      for (int m = 0; m <= n; ++m) {
        const double norm =
            std::sqrt((2 * n + 1) / (4 * kPi)) * std::exp(0.5 * (std::lgamma(n - m + 1.0) - std::lgamma(n + m + 1.0)));
        const std::complex<double> expected =
            (m % 2 ? -1.0 : 1.0) * norm * std::assoc_legendre(n, m, std::cos(theta)) * std::polar(1.0, m * 0.4);
        EXPECT_NEAR(std::abs(y[static_cast<std::size_t>(sh_index(n, m))] - expected), 0, 1e-11)
            << "n " << n << " m " << m << " theta " << theta;
      }
    }
  }
}

TEST(SphericalHarmonics, QuadratureMakesThemOrthonormal) {
  const int degree = 12;
  const SphereQuadrature q = sphere_quadrature(degree);
  double total = 0;
  for (double w : q.weights) total += w;
  EXPECT_NEAR(total, 4 * kPi, 1e-12);
  // Project each Y_nm itself: the result is the unit coefficient at (n, m) and nothing else.
  for (const auto& [n, m] : {std::pair{0, 0}, {3, -2}, {7, 5}, {12, 12}, {12, -11}}) {
    std::vector<double> re(q.directions.size()), im(q.directions.size());
    for (std::size_t i = 0; i < re.size(); ++i) {
      const std::complex<double> v = y_of(n, m, polar_angle(q.directions[i]), azimuth(q.directions[i]));
      re[i] = v.real();
      im[i] = v.imag();
    }
    const ShCoefficients cr = sh_project(q, re, degree), ci = sh_project(q, im, degree);
    for (int nn = 0; nn <= degree; ++nn) {
      for (int mm = -nn; mm <= nn; ++mm) {
        const std::complex<double> a = cr.at(nn, mm) + std::complex<double>(0, 1) * ci.at(nn, mm);
        EXPECT_NEAR(std::abs(a - (nn == n && mm == m ? 1.0 : 0.0)), 0, 1e-12) << n << " " << m << " / " << nn << " " << mm;
      }
    }
  }
}

// A real random surface of degree `degree`: a_{n,-m} = (-1)^m conj(a_nm).
ShCoefficients random_real(int degree, std::uint64_t seed) {
  Rng rng(seed);
  ShCoefficients c(degree);
  c.at(0, 0) = 4;
  for (int n = 1; n <= degree; ++n) {
    for (int m = 0; m <= n; ++m) {
      const std::complex<double> a(rng.uniform() - 0.5, m == 0 ? 0 : rng.uniform() - 0.5);
      c.at(n, m) = a / double(n);
      if (m > 0) c.at(n, -m) = (m % 2 ? -1.0 : 1.0) * std::conj(c.at(n, m));
    }
  }
  return c;
}

TEST(SphericalHarmonics, ProjectionRecoversABandLimitedFunctionExactly) {
  const ShCoefficients c = random_real(10, 3);
  const SphereQuadrature q = sphere_quadrature(10);
  std::vector<double> r;
  for (const Vec3& u : q.directions) r.push_back(sh_radius(c, u));
  const ShCoefficients back = sh_project(q, r, 10);
  for (std::size_t i = 0; i < c.a.size(); ++i) EXPECT_NEAR(std::abs(back.a[i] - c.a[i]), 0, 1e-12) << i;
}

TEST(SphericalHarmonics, RadiiRowByRowEqualThePointwiseSum) {
  ShCoefficients c = random_real(30, 9);
  c.at(7, -3) += std::complex<double>(0.2, -0.1);  // break the symmetry: the real part of the sum all the same
  const SphereQuadrature q = sphere_quadrature(60);
  const std::vector<double> r = sh_radii(c, q);
  ASSERT_EQ(r.size(), q.directions.size());
  for (std::size_t i = 0; i < r.size(); i += 7) EXPECT_NEAR(r[i], sh_radius(c, q.directions[i]), 1e-12) << i;
}

TEST(SphericalHarmonics, DegreeAmplitudesDoNotChangeUnderRotation) {
  const ShCoefficients c = random_real(8, 5);
  const Mat3 rot = (Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()) * Eigen::AngleAxisd(2.1, Vec3::UnitZ()))
                       .toRotationMatrix();
  const SphereQuadrature q = sphere_quadrature(8);
  std::vector<double> r;  // r'(u) = r(R^T u): the surface turned by R
  for (const Vec3& u : q.directions) r.push_back(sh_radius(c, rot.transpose() * u));
  const ShCoefficients turned = sh_project(q, r, 8);
  const std::vector<double> a = sh_degree_amplitudes(c), b = sh_degree_amplitudes(turned);
  ASSERT_EQ(a.size(), 9u);
  EXPECT_EQ(a[0], 1.0);
  for (std::size_t n = 1; n < a.size(); ++n) {
    EXPECT_GT(std::abs(turned.at(static_cast<int>(n), 0) - c.at(static_cast<int>(n), 0)), 1e-3);  // the a_nm moved
    EXPECT_NEAR(a[n], b[n], 1e-12) << n;
  }
}

}  // namespace
}  // namespace grainlab
