// Random SH grains from a spectrum (see sh_generator.h).
//
// A surface r(u) = Re sum a_nm Y_nm(u) is real when a_{n,-m} = (-1)^m
// conj(a_nm) (then the sum is real term by term, as Y_{n,-m} = (-1)^m
// conj(Y_nm)). Degree n then has 2n + 1 real degrees of freedom: a_n0 = x_0
// (real) and a_nm = (x_m + i y_m) / sqrt(2) for m = 1..n, whose squared
// amplitude A_n^2 = sum_{|m|<=n} |a_nm|^2 = x_0^2 + sum_{m>0} (x_m^2 + y_m^2)
// is the squared length of the real vector (x_0, x_1, y_1, ..., x_n, y_n).
// The real spherical harmonics are an orthonormal basis of degree n, and a
// rotation of the grain turns this vector by an orthogonal matrix; so drawing
// its 2n + 1 components as independent standard normals and scaling the
// vector to the length wanted gives a direction uniform on the sphere of that
// dimension: a grain with no preferred orientation and the chosen A_n.
//
// Amplitudes: A_n / A_0 is positive and skewed over a real set's grains, so
// each grain draws it from the lognormal with the set's mean mu and standard
// deviation s: sigma^2 = ln(1 + s^2 / mu^2), ln-mean ln(mu) - sigma^2 / 2
// (whose mean and standard deviation are then exactly mu and s). Degrees are
// drawn independently of each other. a_00 = sqrt(4 pi) makes the mean radius
// 1; the grain is scaled afterwards to a d_eq drawn the same way from the
// set's d_eq (clamped to its range). Scaling every a_nm by one factor keeps
// every A_n / A_0.
//
// A draw whose r <= 0 somewhere is not a star-shaped surface and is drawn
// again (sh_mesh checks the mesh's vertices and a finer grid); the rejection
// favours smaller amplitudes, which only matters for spectra near the limit
// (the count of rejected draws is returned so that this can be seen).
#include "grains/sh_generator.h"

#include "core/error.h"
#include "core/parallel.h"
#include "geometry/mass_properties.h"
#include "geometry/shape_metrics.h"
#include "grains/grain_set.h"
#include "grains/sh_grain.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace grainlab {
namespace {

// The lognormal of mean mu and standard deviation s (mu when s = 0; 0 when mu = 0).
double lognormal(double mu, double s, Rng& rng) {
  const double z = rng.normal();  // drawn always, so the sequence does not depend on the values
  if (!(mu > 0)) return 0;
  const double sigma2 = std::log1p((s / mu) * (s / mu));
  return std::exp(std::log(mu) - 0.5 * sigma2 + std::sqrt(sigma2) * z);
}

// Mesh of c, or nothing when r <= 0 at some direction sh_mesh checks.
bool try_mesh(const ShCoefficients& c, int faces, TriMesh& mesh) {
  const SphereQuadrature grid = sphere_quadrature(std::max(2 * c.degree, 60));
  for (const double r : sh_radii(c, grid)) {
    if (!(r > 0)) return false;
  }
  try {
    mesh = sh_mesh(c, faces, "generated grain");
  } catch (const InputError&) {  // r <= 0 at a vertex only
    return false;
  }
  return true;
}

}  // namespace

void validate(const ShSpectrum& s) {
  if (s.mean.empty() || s.mean.size() != s.std.size()) {
    input_error("a spectrum needs as many means as standard deviations, one per degree n = 0..N; got {} and {}",
                s.mean.size(), s.std.size());
  }
  if (std::abs(s.mean[0] - 1) > 1e-3) {
    input_error("spectrum mean[0] = {} must be 1 (it is A_0 / A_0)", s.mean[0]);
  }
  for (std::size_t n = 0; n < s.mean.size(); ++n) {
    if (!(s.mean[n] >= 0) || !(s.std[n] >= 0) || !std::isfinite(s.mean[n]) || !std::isfinite(s.std[n])) {
      input_error("spectrum degree {}: mean {} and std {} of A_n / A_0 must be finite and >= 0", n, s.mean[n],
                  s.std[n]);
    }
  }
  validate(s.model);
  if (s.model.degree > s.degree()) {
    input_error("the shape model's degree {} is above the spectrum's {}", s.model.degree, s.degree());
  }
  if (!(s.d_eq_min > 0 && s.d_eq_min <= s.d_eq_mean && s.d_eq_mean <= s.d_eq_max && s.d_eq_std >= 0) ||
      !std::isfinite(s.d_eq_max) || !std::isfinite(s.d_eq_std)) {
    input_error("spectrum d_eq (m) must satisfy 0 < min <= mean <= max and std >= 0, got mean {}, std {}, min {}, "
                "max {}",
                s.d_eq_mean, s.d_eq_std, s.d_eq_min, s.d_eq_max);
  }
}

void set_random_degree(ShCoefficients& c, int n, double amplitude, Rng& rng) {
  std::vector<double> x(static_cast<std::size_t>(2 * n + 1));
  double length2 = 0;
  for (double& v : x) {
    v = rng.normal();
    length2 += v * v;
  }
  const double k = length2 > 0 ? amplitude / std::sqrt(length2) : 0;
  c.at(n, 0) = k * x[0];
  for (int m = 1; m <= n; ++m) {
    c.at(n, m) = std::complex<double>(x[2 * m - 1], x[2 * m]) * (k / std::numbers::sqrt2);
    c.at(n, -m) = (m % 2 ? -1.0 : 1.0) * std::conj(c.at(n, m));
  }
}

const char* sh_method_name(ShMethod method) {
  return method == ShMethod::shape_model ? "shape-model" : "random-phase";
}

ShMethod parse_sh_method(const std::string& name) {
  for (const ShMethod m : {ShMethod::random_phase, ShMethod::shape_model}) {
    if (name == sh_method_name(m)) return m;
  }
  input_error("unknown SH generation method '{}'; use \"shape-model\" (the set's principal components) or "
              "\"random-phase\" (its per-degree amplitudes only)",
              name);
}

ShCoefficients draw_sh_coefficients(const ShSpectrum& spectrum, Rng& rng, ShMethod method) {
  if (method == ShMethod::shape_model) {
    ShCoefficients c = draw_from_model(spectrum.model, spectrum.degree(), rng);
    const double a00 = c.at(0, 0).real();
    for (int n = spectrum.model.degree + 1; n <= c.degree; ++n) {
      set_random_degree(c, n, a00 * lognormal(spectrum.mean[n], spectrum.std[n], rng), rng);
    }
    return c;
  }
  ShCoefficients c(spectrum.degree());
  const double a00 = std::sqrt(4 * std::numbers::pi);
  c.at(0, 0) = a00;
  for (int n = 1; n <= c.degree; ++n) {
    const double amplitude = a00 * lognormal(spectrum.mean[n], spectrum.std[n], rng);
    set_random_degree(c, n, amplitude, rng);
  }
  return c;
}

double draw_equivalent_diameter(const ShSpectrum& spectrum, Rng& rng) {
  return std::clamp(lognormal(spectrum.d_eq_mean, spectrum.d_eq_std, rng), spectrum.d_eq_min, spectrum.d_eq_max);
}

ShGrains generate_sh_grains(const ShSpectrum& spectrum, int count, std::uint64_t seed, int faces, ShMethod method) {
  validate(spectrum);
  if (method == ShMethod::shape_model && spectrum.model.empty()) {
    input_error("the shape-model method needs a spectrum with a [model] (write it with `grainlab grains spectrum "
                "--model-degree K`); this one has only per-degree amplitudes: use the random-phase method");
  }
  if (count < 1) input_error("grain count must be at least 1, got {}", count);
  if (faces < 8) input_error("a grain mesh needs at least 8 faces, asked for {}", faces);
  Rng rng(seed);
  std::vector<std::uint64_t> seeds(static_cast<std::size_t>(count));
  for (auto& s : seeds) s = rng.next_u64();

  ShGrains out;
  out.coefficients.resize(seeds.size());
  out.meshes.resize(seeds.size());
  std::vector<int> rejected(seeds.size(), 0);
  std::vector<char> failed(seeds.size(), 0);
  parallel_for(
      count,
      [&](std::ptrdiff_t k) {
        Rng grain_rng(seeds[k]);
        const double d_eq = draw_equivalent_diameter(spectrum, grain_rng);
        ShCoefficients c = draw_sh_coefficients(spectrum, grain_rng, method);
        TriMesh mesh;
        while (!try_mesh(c, faces, mesh)) {
          if (++rejected[k] == kMaxShDraws) {
            failed[k] = 1;
            return;
          }
          c = draw_sh_coefficients(spectrum, grain_rng, method);
        }
        const double s = d_eq / std::cbrt(6 * mass_properties(mesh).volume / std::numbers::pi);
        for (auto& a : c.a) a *= s;
        for (Vec3& v : mesh.vertices) v *= s;
        move_to_principal_frame(mesh);
        out.coefficients[k] = std::move(c);
        out.meshes[k] = std::move(mesh);
      },
      1);
  for (int k = 0; k < count; ++k) {
    if (failed[k]) {
      input_error("grain {} of the spectrum had r <= 0 somewhere in each of {} draws: its amplitudes A_n / A_0 "
                  "(sum of the means {:.3g}) are too large for a star-shaped grain; lower them, or keep fewer "
                  "degrees (`grains spectrum --max-degree`)",
                  k + 1, kMaxShDraws, [&] {
                    double sum = 0;
                    for (std::size_t n = 1; n < spectrum.mean.size(); ++n) sum += spectrum.mean[n];
                    return sum;
                  }());
    }
    out.rejected += rejected[k];
  }
  return out;
}

}  // namespace grainlab
