// Rose histogram and Kanatani grid (definitions in rose.h).
#include "analysis/rose.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace grainlab::analysis {

namespace {

// Bin of x in `bins` equal bins over [lo, hi], the last one closed.
std::size_t bin_of(double x, double lo, double hi, std::size_t bins) {
  const double t = (x - lo) / (hi - lo) * static_cast<double>(bins);
  return static_cast<std::size_t>(std::clamp(std::floor(t), 0.0, static_cast<double>(bins - 1)));
}

std::vector<double> edges(double lo, double hi, std::size_t bins) {
  std::vector<double> e(bins + 1);
  for (std::size_t i = 0; i <= bins; ++i) e[i] = lo + (hi - lo) * static_cast<double>(i) / static_cast<double>(bins);
  return e;
}

}  // namespace

RoseHistogram rose_histogram(std::span<const Vec3> normals) {
  RoseHistogram h;
  if (normals.empty()) return h;
  const double pi = std::numbers::pi;
  const double both = 2.0 * static_cast<double>(normals.size());
  const std::size_t n_z = static_cast<std::size_t>(std::clamp(std::lround(std::sqrt(both / 50.0)), 5L, 18L));
  const std::size_t n_az = 2 * n_z;
  h.z_edges = edges(-1, 1, n_z);
  h.azimuth_edges = edges(-pi, pi, n_az);
  h.density.assign(n_z * n_az, 0.0);
  for (const Vec3& v : normals) {
    const double len = v.norm();
    if (!(len > 0)) throw std::invalid_argument("rose_histogram: a zero normal");
    for (const Vec3& n : {Vec3(v / len), Vec3(-v / len)})
      h.density[bin_of(std::clamp(n.z(), -1.0, 1.0), -1, 1, n_z) * n_az + bin_of(std::atan2(n.y(), n.x()), -pi, pi, n_az)] += 1;
  }
  const double omega = 4 * pi / static_cast<double>(n_z * n_az);
  for (double& d : h.density) d /= both * omega;
  return h;
}

DensityGrid sample_density(const KanataniDensity& f, int n_theta, int n_phi) {
  if (n_theta < 2 || n_phi < 2) throw std::invalid_argument("sample_density: at least 2 x 2 grid points");
  DensityGrid g;
  g.theta = edges(0, std::numbers::pi, static_cast<std::size_t>(n_theta - 1));
  g.phi = edges(-std::numbers::pi, std::numbers::pi, static_cast<std::size_t>(n_phi - 1));
  g.density.reserve(g.theta.size() * g.phi.size());
  for (double t : g.theta)
    for (double p : g.phi)
      g.density.push_back(f(Vec3(std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t))));
  return g;
}

}  // namespace grainlab::analysis
