// Spherical harmonics: a star-shaped surface r(theta, phi) as a sum of
// a_nm Y_nm, its evaluation to degree 30 and beyond, and the projection of
// sampled radii onto Y_nm. Derivation and convention in spherical_harmonics.cpp.
#pragma once

#include "core/types.h"

#include <complex>
#include <span>
#include <vector>

namespace grainlab {

// Position of a_nm in ShCoefficients::a: n = 0..degree, m = -n..n in order.
constexpr int sh_index(int n, int m) { return n * n + n + m; }
// Number of coefficients up to `degree`: (degree + 1)^2.
constexpr int sh_count(int degree) { return (degree + 1) * (degree + 1); }

// r(theta, phi) = Re sum_{n <= degree} sum_{|m| <= n} a_nm Y_nm(theta, phi),
// theta the polar angle from +z, phi the azimuth from +x towards +y, with
// Y_nm = (-1)^m sqrt((2n+1)/(4 pi) (n-m)!/(n+m)!) P_n^m(cos theta) e^{i m phi}
// (P_n^m without the Condon-Shortley phase; the same numbers as scipy's
// sph_harm and Garboczi's files) and Y_{n,-m} = (-1)^m conj(Y_nm).
struct ShCoefficients {
  int degree = 0;
  std::vector<std::complex<double>> a;  // sh_count(degree) values, at sh_index(n, m)

  explicit ShCoefficients(int degree_ = 0) : degree(degree_), a(static_cast<std::size_t>(sh_count(degree_))) {}
  std::complex<double>& at(int n, int m) { return a[static_cast<std::size_t>(sh_index(n, m))]; }
  const std::complex<double>& at(int n, int m) const { return a[static_cast<std::size_t>(sh_index(n, m))]; }
};

// Polar angle and azimuth of a direction (any length > 0): theta in [0, pi], phi in (-pi, pi].
double polar_angle(const Vec3& u);
double azimuth(const Vec3& u);
// Unit vector of (theta, phi).
Vec3 direction_of(double theta, double phi);

// Y_nm(theta, phi) for n = 0..degree and m = 0..n, at sh_index(n, m); the
// entries of m < 0 are left as they were (Y_{n,-m} = (-1)^m conj(Y_nm)).
// `y` is resized to sh_count(degree).
void sh_basis(int degree, double theta, double phi, std::vector<std::complex<double>>& y);

// r along direction u (any length > 0), in the coefficients' unit.
double sh_radius(const ShCoefficients& c, const Vec3& u);

// Points and weights that integrate over the unit sphere exactly any product
// of two functions of degree <= band: Gauss-Legendre in cos(theta) (band + 1
// nodes) times band * 2 + 1 equal steps in phi. Weights sum to 4 pi.
struct SphereQuadrature {
  std::vector<Vec3> directions;  // unit vectors: row by row, direction row * n_phi + j at phi = 2 pi j / n_phi
  std::vector<double> weights;   // steradians
  std::vector<double> thetas;    // each row's polar angle
  int n_phi = 0;                 // directions per row
};
SphereQuadrature sphere_quadrature(int band);

// r at every direction of q, the same values as sh_radius, computed row by
// row: the Legendre sums once per row and degree, then a sum over m per
// direction (about 15 times faster than sh_radius at degree 30 and band 60).
std::vector<double> sh_radii(const ShCoefficients& c, const SphereQuadrature& q);

// a_nm = integral of f conj(Y_nm) over the sphere, from f's values at the
// quadrature's directions, for n <= degree. Exact for f of degree <= band
// (band >= degree); for any other f, the least-squares fit in the L2 sense
// up to the aliasing of degrees above band.
ShCoefficients sh_project(const SphereQuadrature& q, std::span<const double> values, int degree);

// The rotation-invariant amplitude of each degree, A_n = sqrt(sum_m |a_nm|^2),
// divided by A_0 = |a_00|: n = 0..degree (the first is 1). A rotation of the
// surface mixes the a_nm of one degree unitarily, so A_n does not change.
std::vector<double> sh_degree_amplitudes(const ShCoefficients& c);

}  // namespace grainlab
