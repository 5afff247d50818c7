// Statistical shape model of SH grains (see sh_shape_model.h).
//
// Real coordinates. For a real r, a_{n,-m} = (-1)^m conj(a_nm), so degree n
// has the 2n + 1 real numbers a_n0, Re a_nm, Im a_nm (m = 1..n) and
// sum_{|m|<=n} |a_nm|^2 = a_n0^2 + 2 sum_{m>0} |a_nm|^2. With x_{n,0} = a_n0,
// x_{n,m} = sqrt 2 Re a_nm, x_{n,-m} = sqrt 2 Im a_nm the Euclidean length of
// the degree's block is A_n and the dot product of two vectors is the L2
// inner product of the two surfaces over the sphere: distances, means and
// principal components in x are those of the radial functions themselves.
//
// Alignment. A set's coefficients can only be averaged once the grains share
// a pose: each grain is rotated so that its principal axes of inertia (long,
// intermediate, short) lie on x, y, z. The axes' signs are ambiguous (an
// ellipsoid is the same each way); each is chosen so that the third moment
// sum_v ((v - centroid) . e)^3 over the mesh's vertices is >= 0, i.e. the
// grain's heavier tail lies on +e. Q may then be a reflection; a mirrored
// grain is as much a grain of the set as the grain itself (sands have no
// handedness). r'(u) = r(Q u) is again of degree N (a rotation mixes
// coefficients within a degree only); sampled on a quadrature exact for
// products of degree 2N and projected on Y_nm (sh_project), it is exact to
// rounding. The origin stays the file's (VCCTL's lie within 2.3 % of d_eq of
// the centroid).
//
// Principal components. With G grains x_g (normalised by a_00, so x_{0,0} =
// 1 for all), mean m and centred rows X = [x_g - m], the covariance is
// X^T X / (G - 1). Its non-zero eigenvectors come from the G x G Gram matrix
// X X^T = U L U^T: v_i = X^T u_i / sqrt(l_i), with variance sigma_i^2 = l_i /
// (G - 1). Keeping k < G - 1 of them, the rest of each grain's deviation
// (x_g - m minus its projection on v_1..v_k) is summed per degree into
// residual[n]^2 = sum_g |res_{g,n}|^2 / (G - 1), so that the model's
// per-degree variance sum_i sigma_i^2 |v_{i,n}|^2 + residual[n]^2 is the
// set's. A draw x = m + sum_i z_i sigma_i v_i (z_i standard normal) has the
// set's mean and, within the span kept, its covariance: the correlations
// between coefficients within and across degrees that decide flatness,
// convexity and where the relief sits (random phases lose them, docs/grains.md).
#include "grains/sh_shape_model.h"

#include "core/error.h"
#include "geometry/mass_properties.h"
#include "geometry/shape_metrics.h"
#include "grains/sh_generator.h"
#include "grains/sh_grain.h"

#include <Eigen/Eigenvalues>

#include <cmath>
#include <numbers>

namespace grainlab {

std::vector<double> sh_real_vector(const ShCoefficients& c, int degree) {
  std::vector<double> x(static_cast<std::size_t>(sh_count(degree)), 0.0);
  for (int n = 0; n <= std::min(degree, c.degree); ++n) {
    x[sh_index(n, 0)] = c.at(n, 0).real();
    for (int m = 1; m <= n; ++m) {
      x[sh_index(n, m)] = std::numbers::sqrt2 * c.at(n, m).real();
      x[sh_index(n, -m)] = std::numbers::sqrt2 * c.at(n, m).imag();
    }
  }
  return x;
}

ShCoefficients sh_from_real_vector(const std::vector<double>& x, int degree) {
  ShCoefficients c(degree);
  for (int n = 0; n <= degree; ++n) {
    c.at(n, 0) = x[sh_index(n, 0)];
    for (int m = 1; m <= n; ++m) {
      c.at(n, m) = std::complex<double>(x[sh_index(n, m)], x[sh_index(n, -m)]) / std::numbers::sqrt2;
      c.at(n, -m) = (m % 2 ? -1.0 : 1.0) * std::conj(c.at(n, m));
    }
  }
  return c;
}

ShCoefficients sh_aligned(const ShCoefficients& c, int faces) {
  const TriMesh mesh = sh_mesh(c, faces, "grain to align");
  const PrincipalFrame frame = principal_frame(mesh);
  Mat3 q = frame.axes;
  for (int k = 0; k < 3; ++k) {
    double third = 0;
    for (const Vec3& v : mesh.vertices) third += std::pow((v - frame.centroid).dot(q.col(k)), 3);
    if (third < 0) q.col(k) = -q.col(k);
  }
  const SphereQuadrature grid = sphere_quadrature(c.degree);
  std::vector<double> r(grid.directions.size());
  for (std::size_t i = 0; i < r.size(); ++i) r[i] = sh_radius(c, q * grid.directions[i]);
  return sh_project(grid, r, c.degree);
}

void validate(const ShShapeModel& model) {
  if (model.empty()) return;
  const std::size_t d = static_cast<std::size_t>(sh_count(model.degree));
  if (model.mean.size() != d) {
    input_error("shape model of degree {} needs {} mean values ((degree + 1)^2), got {}", model.degree, d,
                model.mean.size());
  }
  if (std::abs(model.mean[0] - 1) > 1e-6) input_error("shape model mean[0] = {} must be 1 (a_00 / a_00)", model.mean[0]);
  if (model.residual.size() != static_cast<std::size_t>(model.degree + 1)) {
    input_error("shape model of degree {} needs {} residual values (one per degree), got {}", model.degree,
                model.degree + 1, model.residual.size());
  }
  if (model.components.size() != model.sigma.size()) {
    input_error("shape model has {} components but {} sigma values; it needs one sigma per component",
                model.components.size(), model.sigma.size());
  }
  for (const double v : model.mean) {
    if (!std::isfinite(v)) input_error("shape model mean holds a value that is not finite ({})", v);
  }
  for (std::size_t i = 0; i < model.sigma.size(); ++i) {
    if (!(model.sigma[i] >= 0) || !std::isfinite(model.sigma[i])) {
      input_error("shape model sigma[{}] = {} must be finite and >= 0", i, model.sigma[i]);
    }
  }
  for (std::size_t n = 0; n < model.residual.size(); ++n) {
    if (!(model.residual[n] >= 0) || !std::isfinite(model.residual[n])) {
      input_error("shape model residual[{}] = {} must be finite and >= 0", n, model.residual[n]);
    }
  }
  for (std::size_t i = 0; i < model.components.size(); ++i) {
    const auto& v = model.components[i];
    if (v.size() != d) {
      input_error("shape model component {} has {} values; degree {} needs {}", i, v.size(), model.degree, d);
    }
    double length2 = 0;
    for (const double x : v) length2 += x * x;
    if (!(std::abs(std::sqrt(length2) - 1) < 1e-4)) {
      input_error("shape model component {} has length {}; components are unit vectors", i, std::sqrt(length2));
    }
  }
}

ShShapeModel fit_sh_shape_model(const std::vector<ShCoefficients>& grains, int degree, int components, int faces) {
  const int g = static_cast<int>(grains.size());
  if (g < 2) input_error("a shape model needs at least 2 grains, got {}", g);
  if (degree < 0) input_error("shape model degree must be >= 0, got {}", degree);
  const int d = sh_count(degree);
  Eigen::MatrixXd x(g, d);
  for (int i = 0; i < g; ++i) {
    if (grains[i].degree < degree) {
      input_error("grain {} has degree {}, below the model's {}", i + 1, grains[i].degree, degree);
    }
    const std::vector<double> v = sh_real_vector(sh_aligned(truncated(grains[i], degree), faces), degree);
    for (int j = 0; j < d; ++j) x(i, j) = v[j] / v[0];
  }
  ShShapeModel model;
  model.degree = degree;
  const Eigen::RowVectorXd mean = x.colwise().mean();
  model.mean.assign(mean.data(), mean.data() + d);
  const Eigen::MatrixXd xc = x.rowwise() - mean;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(xc * xc.transpose());
  const double total = eig.eigenvalues().sum();
  Eigen::MatrixXd kept(d, 0);
  for (int i = g - 1; i >= 0 && static_cast<int>(model.components.size()) < components; --i) {
    const double l = eig.eigenvalues()(i);
    if (!(l > 1e-12 * total)) break;
    const Eigen::VectorXd v = xc.transpose() * eig.eigenvectors().col(i) / std::sqrt(l);
    model.components.emplace_back(v.data(), v.data() + d);
    model.sigma.push_back(std::sqrt(l / (g - 1)));
    kept.conservativeResize(d, kept.cols() + 1);
    kept.col(kept.cols() - 1) = v;
  }
  const Eigen::MatrixXd res = xc - (xc * kept) * kept.transpose();
  model.residual.assign(static_cast<std::size_t>(degree + 1), 0.0);
  for (int n = 0; n <= degree; ++n) {
    double ss = 0;
    for (int j = sh_index(n, -n); j <= sh_index(n, n); ++j) ss += res.col(j).squaredNorm();
    model.residual[n] = std::sqrt(ss / (g - 1));
  }
  return model;
}

ShCoefficients draw_from_model(const ShShapeModel& model, int out_degree, Rng& rng) {
  std::vector<double> x = model.mean;
  for (std::size_t i = 0; i < model.components.size(); ++i) {
    const double s = model.sigma[i] * rng.normal();
    for (std::size_t j = 0; j < x.size(); ++j) x[j] += s * model.components[i][j];
  }
  const ShCoefficients low = sh_from_real_vector(x, model.degree);
  ShCoefficients c(out_degree);
  ShCoefficients relief(model.degree);
  for (int n = 1; n <= model.degree; ++n) set_random_degree(relief, n, model.residual[n], rng);
  for (int n = 0; n <= model.degree; ++n) {
    for (int m = -n; m <= n; ++m) c.at(n, m) = low.at(n, m) + relief.at(n, m);
  }
  return c;
}

double unexplained_fraction(const ShShapeModel& model, const std::vector<double>& x) {
  std::vector<double> d(model.mean.size());
  double d2 = 0;
  for (std::size_t j = 0; j < d.size(); ++j) {
    d[j] = x[j] - model.mean[j];
    d2 += d[j] * d[j];
  }
  if (!(d2 > 0)) return 0;
  for (const auto& v : model.components) {
    double s = 0;
    for (std::size_t j = 0; j < d.size(); ++j) s += d[j] * v[j];
    for (std::size_t j = 0; j < d.size(); ++j) d[j] -= s * v[j];
  }
  double r2 = 0;
  for (const double v : d) r2 += v * v;
  return std::sqrt(r2 / d2);
}

}  // namespace grainlab
