// The SH shape model: real coordinates round trip and carry A_n; alignment
// puts a rotated ellipsoid's axes on x, y, z; a model of synthetic grains
// (rotated ellipsoids of known axes) generates grains whose elongation,
// flatness and sphericity match the sources' and that are none of them;
// generation is the same on any thread count, and the random-phase method
// ignores a model (old spectra keep their meaning).
#include "grains/sh_shape_model.h"

#include "geometry/mass_properties.h"
#include "geometry/shape_metrics.h"
#include "geometry/test_helpers.h"
#include "grains/grain_set.h"
#include "grains/sh_generator.h"
#include "grains/sh_grain.h"
#include "grains/sh_sands.h"
#include "sh_test_shapes.h"

#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace grainlab {
namespace {

// The ellipsoid of semi-axes a, b, c along the columns of `axes`, projected to `degree`.
ShCoefficients rotated_ellipsoid(double a, double b, double c, const Mat3& axes, int degree) {
  const SphereQuadrature q = sphere_quadrature(2 * degree);
  std::vector<double> r;
  for (const Vec3& u : q.directions) {
    const Vec3 v = axes.transpose() * u;
    r.push_back(1 / std::sqrt(v.x() * v.x() / (a * a) + v.y() * v.y() / (b * b) + v.z() * v.z() / (c * c)));
  }
  return sh_project(q, r, degree);
}

Mat3 random_rotation(Rng& rng) {
  return Quat(rng.normal(), rng.normal(), rng.normal(), rng.normal()).normalized().toRotationMatrix();
}

// 16 rotated ellipsoids, b / a uniform in [0.6, 0.9], c / b in [0.55, 0.9].
std::vector<ShCoefficients> ellipsoid_set(int degree) {
  Rng rng(11);
  std::vector<ShCoefficients> set;
  for (int k = 0; k < 16; ++k) {
    const double b = rng.uniform(0.6, 0.9), c = b * rng.uniform(0.55, 0.9);
    set.push_back(rotated_ellipsoid(1, b, c, random_rotation(rng), degree));
  }
  return set;
}

// The spectrum (per-degree means and spreads) of a set, with a nominal size.
ShSpectrum spectrum_of(const std::vector<ShCoefficients>& set) {
  ShSpectrum s;
  const int degree = set[0].degree;
  for (int n = 0; n <= degree; ++n) {
    double sum = 0, sum2 = 0;
    for (const auto& c : set) {
      const double a = sh_degree_amplitudes(c)[n];
      sum += a;
      sum2 += a * a;
    }
    const double mean = sum / set.size();
    s.mean.push_back(mean);
    s.std.push_back(std::sqrt(std::max(0.0, sum2 / set.size() - mean * mean)));
  }
  s.d_eq_mean = 1e-3;
  s.d_eq_std = 0.1e-3;
  s.d_eq_min = 0.8e-3;
  s.d_eq_max = 1.2e-3;
  return s;
}

struct Means {
  double elongation = 0, flatness = 0, sphericity = 0;
};

// Means of I / L, S / I (principal extents, as shape_metrics) and Wadell sphericity.
Means means_of(const std::vector<TriMesh>& meshes) {
  Means m;
  for (const TriMesh& mesh : meshes) {
    const Vec3 e = principal_frame(mesh).extents;
    double area = 0;
    for (const auto& f : mesh.faces) {
      const Vec3 &a = mesh.vertices[f[0]], &b = mesh.vertices[f[1]], &c = mesh.vertices[f[2]];
      area += 0.5 * (b - a).cross(c - a).norm();
    }
    const double volume = mass_properties(mesh).volume;
    m.elongation += e.y() / e.x() / meshes.size();
    m.flatness += e.z() / e.y() / meshes.size();
    m.sphericity += std::cbrt(std::numbers::pi) * std::pow(6 * volume, 2.0 / 3) / area / meshes.size();
  }
  return m;
}

double distance(const std::vector<double>& a, const std::vector<double>& b) {
  double d2 = 0;
  for (std::size_t j = 0; j < a.size(); ++j) d2 += (a[j] - b[j]) * (a[j] - b[j]);
  return std::sqrt(d2);
}

// The aligned real vector of a grain, normalised by a_00.
std::vector<double> aligned_vector(const ShCoefficients& c, int degree) {
  std::vector<double> x = sh_real_vector(sh_aligned(truncated(c, degree), 600), degree);
  const double a00 = x[0];
  for (double& v : x) v /= a00;
  return x;
}

TEST(ShShapeModel, RealVectorsRoundTripAndHoldTheDegreeAmplitudes) {
  const ShCoefficients c = test::lumpy_grain(6, 3);
  const std::vector<double> x = sh_real_vector(c, 6);
  const ShCoefficients back = sh_from_real_vector(x, 6);
  for (std::size_t i = 0; i < c.a.size(); ++i) EXPECT_NEAR(std::abs(back.a[i] - c.a[i]), 0, 1e-15) << i;
  const std::vector<double> amplitude = sh_degree_amplitudes(c);
  for (int n = 0; n <= 6; ++n) {
    double ss = 0;
    for (int m = -n; m <= n; ++m) ss += x[sh_index(n, m)] * x[sh_index(n, m)];
    EXPECT_NEAR(std::sqrt(ss), amplitude[n] * std::abs(c.at(0, 0)), 1e-12) << "degree " << n;
  }
}

TEST(ShShapeModel, AlignmentPutsTheLongIntermediateAndShortAxesOnXYZ) {
  Rng rng(4);
  const ShCoefficients c = sh_aligned(rotated_ellipsoid(1, 0.7, 0.5, random_rotation(rng), 16), 2000);
  EXPECT_NEAR(sh_radius(c, Vec3::UnitX()), 1, 2e-3);
  EXPECT_NEAR(sh_radius(c, Vec3::UnitY()), 0.7, 2e-3);
  EXPECT_NEAR(sh_radius(c, Vec3::UnitZ()), 0.5, 2e-3);
  EXPECT_NEAR(sh_radius(c, -Vec3::UnitX()), 1, 2e-3);
  // An egg (a grain with a heavier end): the heavier end goes to +x, whatever the pose.
  ShCoefficients egg = rotated_ellipsoid(1, 0.7, 0.5, Mat3::Identity(), 12);
  egg.at(3, 0) = 0.1;  // Y_30 is odd along z
  const Mat3 turn = random_rotation(rng);
  const ShCoefficients a = sh_aligned(egg, 2000);
  const SphereQuadrature q = sphere_quadrature(12);
  std::vector<double> r;
  for (const Vec3& u : q.directions) r.push_back(sh_radius(egg, turn.transpose() * u));
  const ShCoefficients b = sh_aligned(sh_project(q, r, 12), 2000);
  // (the same up to the two meshes' principal axes: 1e-4 of a_00 = 3.5)
  for (std::size_t i = 0; i < a.a.size(); ++i) EXPECT_NEAR(std::abs(a.a[i] - b.a[i]), 0, 1e-4) << i;
}

TEST(ShShapeModel, GeneratedGrainsMatchTheSourcesAndAreNoneOfThem) {
  const std::vector<ShCoefficients> sources = ellipsoid_set(8);
  ShSpectrum s = spectrum_of(sources);
  s.model = fit_sh_shape_model(sources, 8, 15, 600);
  ASSERT_NO_THROW(validate(s));
  EXPECT_EQ(s.model.components.size(), 15u);
  for (double r : s.model.residual) EXPECT_LT(r, 1e-9);  // all components kept: nothing left over
  const ShShapeModel few = fit_sh_shape_model(sources, 8, 2, 600);
  EXPECT_EQ(few.components.size(), 2u);
  EXPECT_GT(few.residual[2] + few.residual[4], 0);

  std::vector<TriMesh> source_meshes;
  for (const auto& c : sources) source_meshes.push_back(sh_mesh(c, 600, "source"));
  const ShGrains g = generate_sh_grains(s, 50, 3, 600, ShMethod::shape_model);
  const Means real = means_of(source_meshes), generated = means_of(g.meshes);
  EXPECT_NEAR(generated.elongation, real.elongation, 0.03);
  EXPECT_NEAR(generated.flatness, real.flatness, 0.03);
  EXPECT_NEAR(generated.sphericity, real.sphericity, 0.01);
  // The random-phase method misses the flatness of these ellipsoids (their
  // degree-2 forms are not random directions): the model is what makes the match.
  const ShGrains p = generate_sh_grains(s, 50, 3, 600, ShMethod::random_phase);
  EXPECT_GT(std::abs(means_of(p.meshes).flatness - real.flatness), 0.03);

  // Not copies: a generated grain lies about as far from its nearest source
  // as the sources lie from each other.
  std::vector<std::vector<double>> x;
  for (const auto& c : sources) x.push_back(aligned_vector(c, 8));
  double source_gap = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    double nearest = 1e9;
    for (std::size_t j = 0; j < x.size(); ++j)
      if (j != i) nearest = std::min(nearest, distance(x[i], x[j]));
    source_gap += nearest / x.size();
  }
  double generated_gap = 0, closest = 1e9;
  for (int k = 0; k < 20; ++k) {
    const std::vector<double> y = aligned_vector(g.coefficients[k], 8);
    double nearest = 1e9;
    for (const auto& xi : x) nearest = std::min(nearest, distance(y, xi));
    generated_gap += nearest / 20;
    closest = std::min(closest, nearest);
  }
  EXPECT_GT(generated_gap, 0.5 * source_gap);
  EXPECT_GT(closest, 0.05 * source_gap);
  // The model's span holds each source (all components kept), two components only part of it.
  EXPECT_LT(unexplained_fraction(s.model, x[0]), 1e-6);
  EXPECT_GT(unexplained_fraction(few, x[0]), 1e-3);
}

TEST(ShShapeModel, SameGrainsOnAnyThreadCountAndRandomPhaseIgnoresTheModel) {
  const std::vector<ShCoefficients> sources = ellipsoid_set(6);
  ShSpectrum s = spectrum_of(sources);
  const ShSpectrum without = s;
  s.model = fit_sh_shape_model(sources, 4, 6, 400);
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const ShGrains one = generate_sh_grains(s, 12, 9, 300, ShMethod::shape_model);
  omp_set_num_threads(3);
  const ShGrains three = generate_sh_grains(s, 12, 9, 300, ShMethod::shape_model);
  omp_set_num_threads(threads);
  for (int k = 0; k < 12; ++k) {
    ASSERT_EQ(one.meshes[k].vertices, three.meshes[k].vertices) << "grain " << k;
    ASSERT_EQ(one.coefficients[k].a, three.coefficients[k].a) << "grain " << k;
  }
  const ShGrains old = generate_sh_grains(without, 5, 9, 300);
  const ShGrains ignoring = generate_sh_grains(s, 5, 9, 300, ShMethod::random_phase);
  for (int k = 0; k < 5; ++k) ASSERT_EQ(old.meshes[k].vertices, ignoring.meshes[k].vertices) << "grain " << k;
  EXPECT_CONTAINS(test::input_error_of([&] { generate_sh_grains(without, 1, 1, 300, ShMethod::shape_model); }),
                  "the shape-model method needs a spectrum with a [model]");
  EXPECT_EQ(parse_sh_method("shape-model"), ShMethod::shape_model);
  EXPECT_CONTAINS(test::input_error_of([&] { parse_sh_method("pca"); }), "unknown SH generation method 'pca'");
}

TEST(ShShapeModel, RefusesInconsistentModels) {
  ShShapeModel m = fit_sh_shape_model(ellipsoid_set(4), 4, 3, 400);
  ASSERT_NO_THROW(validate(m));
  ShShapeModel bad = m;
  bad.mean.pop_back();
  EXPECT_CONTAINS(test::input_error_of([&] { validate(bad); }), "needs 25 mean values");
  bad = m;
  bad.components[1][3] += 0.5;
  EXPECT_CONTAINS(test::input_error_of([&] { validate(bad); }), "component 1 has length");
  bad = m;
  bad.sigma[0] = -1;
  EXPECT_CONTAINS(test::input_error_of([&] { validate(bad); }), "sigma[0] = -1 must be finite and >= 0");
  EXPECT_CONTAINS(test::input_error_of([&] { fit_sh_shape_model({test::lumpy_grain(4)}, 4, 3, 400); }),
                  "at least 2 grains");
}

TEST(ShSands, EmbeddedSandsAreValidAndSizedToTheSieve) {
  ASSERT_EQ(sh_sands().size(), 3u);
  for (const ShSand& sand : sh_sands()) {
    EXPECT_EQ(sand.spectrum.model.degree, 30) << sand.name;
    EXPECT_GT(sand.real.convexity, 0.8) << sand.name;
  }
  const GrainSet set = generate_sh_grain_set("sh-river", 6, 2, SieveRange{0.7e-3, 0.8e-3}, 300);
  ASSERT_EQ(set.meshes.size(), 6u);
  EXPECT_EQ(set.names[0], "sh-river-0001");
  for (const TriMesh& m : set.meshes) {
    EXPECT_GE(size_of(m), 0.7e-3 * (1 - 1e-9));
    EXPECT_LE(size_of(m), 0.8e-3 * (1 + 1e-9));
  }
  EXPECT_CONTAINS(test::input_error_of([&] { generate_sh_grain_set("sh-granite", 1, 1); }),
                  "use one of sh-ottawa, sh-river, sh-limestone");
}

}  // namespace
}  // namespace grainlab
