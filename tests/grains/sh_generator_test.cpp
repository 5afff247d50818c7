// Random SH grains from a spectrum: the drawn amplitudes average to the
// spectrum's means (within 3.5 standard errors of the mean), the surface is
// real and r > 0 everywhere, sizes follow d_eq, the same seed gives the same
// bits, and spectra that cannot give star-shaped grains are refused.
#include "grains/sh_generator.h"

#include "geometry/mass_properties.h"
#include "geometry/mesh_check.h"
#include "geometry/shape_metrics.h"
#include "geometry/test_helpers.h"

#include <gtest/gtest.h>

#include <cmath>

namespace grainlab {
namespace {

// A spectrum of degree 10 falling as n^-1.5 (as the VCCTL sands' do), spread 30 %.
ShSpectrum falling_spectrum() {
  ShSpectrum s;
  for (int n = 0; n <= 10; ++n) {
    s.mean.push_back(n == 0 ? 1.0 : n == 1 ? 0.01 : 0.15 * std::pow(n / 2.0, -1.5));
    s.std.push_back(n == 0 ? 0.0 : 0.3 * s.mean.back());
  }
  s.d_eq_mean = 1e-3;
  s.d_eq_std = 0.2e-3;
  s.d_eq_min = 0.7e-3;
  s.d_eq_max = 1.4e-3;
  return s;
}

TEST(ShGenerator, DegreeAmplitudesAverageToTheSpectrumsMeans) {
  const ShSpectrum s = falling_spectrum();
  const int count = 40;
  const ShGrains g = generate_sh_grains(s, count, 11, 200);
  ASSERT_EQ(g.coefficients.size(), static_cast<std::size_t>(count));
  for (int n = 1; n <= s.degree(); ++n) {
    double sum = 0, sum2 = 0;
    for (const ShCoefficients& c : g.coefficients) {
      const double a = sh_degree_amplitudes(c)[n];
      sum += a;
      sum2 += a * a;
    }
    const double mean = sum / count, spread = std::sqrt(sum2 / count - mean * mean);
    // The mean of `count` draws of spread s.std[n] lies within 3.5 standard errors of s.mean[n].
    EXPECT_NEAR(mean, s.mean[n], 3.5 * s.std[n] / std::sqrt(count)) << "degree " << n;
    EXPECT_NEAR(spread / s.std[n], 1, 0.5) << "degree " << n;
  }
}

TEST(ShGenerator, ExactMeanWithoutSpreadAndARealSurface) {
  ShSpectrum s = falling_spectrum();
  for (double& v : s.std) v = 0;
  Rng rng(3);
  const ShCoefficients c = draw_sh_coefficients(s, rng);
  const std::vector<double> a = sh_degree_amplitudes(c);
  for (int n = 0; n <= s.degree(); ++n) EXPECT_NEAR(a[n], s.mean[n], 1e-14) << "degree " << n;
  for (int n = 0; n <= s.degree(); ++n) {
    EXPECT_EQ(c.at(n, 0).imag(), 0);
    for (int m = 1; m <= n; ++m) EXPECT_EQ(c.at(n, -m), (m % 2 ? -1.0 : 1.0) * std::conj(c.at(n, m)));
  }
}

TEST(ShGenerator, GrainsArePositiveClosedSizedAndReproducible) {
  ShSpectrum s = falling_spectrum();
  for (int n = 2; n <= 4; ++n) s.mean[n] *= 2.5;  // rough enough that some draws reach r <= 0
  const ShGrains a = generate_sh_grains(s, 30, 5, 300);
  EXPECT_GT(a.rejected, 0);
  const SphereQuadrature fine = sphere_quadrature(80);
  for (std::size_t k = 0; k < a.meshes.size(); ++k) {
    for (const double r : sh_radii(a.coefficients[k], fine)) ASSERT_GT(r, 0) << "grain " << k;
    const TriMesh& m = a.meshes[k];
    EXPECT_EQ(m.faces.size(), 300u);
    EXPECT_TRUE(check_mesh(m).ok()) << check_mesh(m).describe();
    EXPECT_LT(mass_properties(m).centroid.norm(), 1e-12);
    const double d = std::cbrt(6 * mass_properties(m).volume / 3.141592653589793);
    EXPECT_GE(d, s.d_eq_min * (1 - 1e-9));
    EXPECT_LE(d, s.d_eq_max * (1 + 1e-9));
  }
  const ShGrains b = generate_sh_grains(s, 30, 5, 300);
  for (std::size_t k = 0; k < a.meshes.size(); ++k) {
    ASSERT_EQ(a.meshes[k].vertices, b.meshes[k].vertices) << "grain " << k;
    ASSERT_EQ(a.coefficients[k].a, b.coefficients[k].a);
  }
  EXPECT_NE(generate_sh_grains(s, 1, 6, 300).meshes[0].vertices, a.meshes[0].vertices);
}

TEST(ShGenerator, RefusesSpectraThatCannotGiveAGrain) {
  ShSpectrum s = falling_spectrum();
  for (int n = 1; n <= s.degree(); ++n) s.mean[n] = 1;  // relief as large as the mean radius
  EXPECT_CONTAINS(test::input_error_of([&] { generate_sh_grains(s, 2, 1, 100); }), "too large for a star-shaped");
  ShSpectrum bad = falling_spectrum();
  bad.std[3] = -0.1;
  EXPECT_CONTAINS(test::input_error_of([&] { validate(bad); }), "degree 3");
  bad = falling_spectrum();
  bad.std.pop_back();
  EXPECT_CONTAINS(test::input_error_of([&] { validate(bad); }), "as many means as standard deviations");
  bad = falling_spectrum();
  bad.d_eq_min = 2e-3;
  EXPECT_CONTAINS(test::input_error_of([&] { validate(bad); }), "0 < min <= mean <= max");
  bad = falling_spectrum();
  bad.mean[0] = 2;
  EXPECT_CONTAINS(test::input_error_of([&] { validate(bad); }), "mean[0] = 2 must be 1");
}

}  // namespace
}  // namespace grainlab
