#include "ct/voxelize.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace grainlab::ct {

namespace {

constexpr double kJitter = 1.2345678e-7;  // keeps sample lines off mesh edges and vertices

// x where the line {(x, y, z)} crosses triangle (a, b, c), if it does (2D point-in-triangle in y, z).
bool line_crossing(const Vec3& a, const Vec3& b, const Vec3& c, double y, double z, double* x) {
  const double d = (b.y() - a.y()) * (c.z() - a.z()) - (c.y() - a.y()) * (b.z() - a.z());
  if (d == 0) return false;
  const double u = ((b.y() - y) * (c.z() - z) - (c.y() - y) * (b.z() - z)) / d;  // weight of a
  const double v = ((c.y() - y) * (a.z() - z) - (a.y() - y) * (c.z() - z)) / d;  // weight of b
  const double w = 1 - u - v;
  if (u < 0 || v < 0 || w < 0) return false;
  *x = u * a.x() + v * b.x() + w * c.x();
  return true;
}

}  // namespace

bool inside_mesh(const TriMesh& mesh, const Vec3& p) {
  int crossings = 0;
  const double y = p.y() + kJitter, z = p.z() + 0.7 * kJitter;
  for (const Face& f : mesh.faces) {
    double x;
    if (line_crossing(mesh.vertices[f[0]], mesh.vertices[f[1]], mesh.vertices[f[2]], y, z, &x) && x > p.x()) {
      ++crossings;
    }
  }
  return crossings % 2 == 1;
}

void add_occupancy(const TriMesh& mesh, int samples, GreyVolume& occ) {
  if (mesh.faces.empty()) return;
  Vec3 lo = mesh.vertices.front(), hi = lo;
  for (const Vec3& v : mesh.vertices) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  const double s = samples;
  // Sample line (m, n) sits at y = (m + 0.5) / s - 0.5, z = (n + 0.5) / s - 0.5 (plus jitter): line m
  // belongs to voxel row floor(m / s).
  auto line_y = [&](std::int64_t m) { return (m + 0.5) / s - 0.5 + kJitter; };
  auto line_z = [&](std::int64_t n) { return (n + 0.5) / s - 0.5 + 0.7 * kJitter; };
  const std::int64_t m0 = std::max<std::int64_t>(0, static_cast<std::int64_t>(std::floor((lo.y() + 0.5) * s)));
  const std::int64_t m1 = std::min<std::int64_t>(occ.size[1] * samples - 1,
                                                 static_cast<std::int64_t>(std::ceil((hi.y() + 0.5) * s)));
  const std::int64_t n0 = std::max<std::int64_t>(0, static_cast<std::int64_t>(std::floor((lo.z() + 0.5) * s)));
  const std::int64_t n1 = std::min<std::int64_t>(occ.size[2] * samples - 1,
                                                 static_cast<std::int64_t>(std::ceil((hi.z() + 0.5) * s)));
  if (m1 < m0 || n1 < n0) return;
  const std::int64_t rows = m1 - m0 + 1, cols = n1 - n0 + 1;
  // Triangles binned by the sample lines their y-z bounding box covers.
  std::vector<std::vector<Index>> bins(static_cast<std::size_t>(rows * cols));
  for (Index t = 0; t < static_cast<Index>(mesh.faces.size()); ++t) {
    const Face& f = mesh.faces[t];
    double ylo = 1e300, yhi = -1e300, zlo = 1e300, zhi = -1e300;
    for (Index c : f) {
      ylo = std::min(ylo, mesh.vertices[c].y());
      yhi = std::max(yhi, mesh.vertices[c].y());
      zlo = std::min(zlo, mesh.vertices[c].z());
      zhi = std::max(zhi, mesh.vertices[c].z());
    }
    const std::int64_t a0 = std::max(m0, static_cast<std::int64_t>(std::floor((ylo + 0.5) * s - 0.5)));
    const std::int64_t a1 = std::min(m1, static_cast<std::int64_t>(std::ceil((yhi + 0.5) * s - 0.5)));
    const std::int64_t b0 = std::max(n0, static_cast<std::int64_t>(std::floor((zlo + 0.5) * s - 0.5)));
    const std::int64_t b1 = std::min(n1, static_cast<std::int64_t>(std::ceil((zhi + 0.5) * s - 0.5)));
    for (std::int64_t m = a0; m <= a1; ++m) {
      for (std::int64_t n = b0; n <= b1; ++n) bins[(m - m0) * cols + (n - n0)].push_back(t);
    }
  }
  const double weight = 1.0 / (s * s);
  const double x_end = occ.size[0] - 0.5;
  std::vector<double> xs;
  for (std::int64_t m = m0; m <= m1; ++m) {
    for (std::int64_t n = n0; n <= n1; ++n) {
      const double y = line_y(m), z = line_z(n);
      xs.clear();
      for (Index t : bins[(m - m0) * cols + (n - n0)]) {
        const Face& f = mesh.faces[t];
        double x;
        if (line_crossing(mesh.vertices[f[0]], mesh.vertices[f[1]], mesh.vertices[f[2]], y, z, &x)) xs.push_back(x);
      }
      std::sort(xs.begin(), xs.end());
      const std::int64_t j = m / samples, k = n / samples;
      for (std::size_t q = 0; q + 1 < xs.size(); q += 2) {
        const double a = std::max(xs[q], -0.5), b = std::min(xs[q + 1], x_end);
        if (b <= a) continue;
        const std::int64_t i0 = static_cast<std::int64_t>(std::floor(a + 0.5));
        const std::int64_t i1 = std::min(occ.size[0] - 1, static_cast<std::int64_t>(std::floor(b + 0.5)));
        for (std::int64_t i = i0; i <= i1; ++i) {
          const double len = std::min(b, i + 0.5) - std::max(a, i - 0.5);
          if (len > 0) occ.at(i, j, k) += static_cast<float>(len * weight);
        }
      }
    }
  }
}

void gaussian_blur(GreyVolume& v, double sigma) {
  if (sigma <= 0) return;
  const int r = static_cast<int>(std::ceil(3 * sigma));
  std::vector<double> kernel(2 * r + 1);
  double sum = 0;
  for (int q = -r; q <= r; ++q) sum += kernel[q + r] = std::exp(-0.5 * q * q / (sigma * sigma));
  for (double& w : kernel) w /= sum;
  const std::int64_t n[3] = {v.size[0], v.size[1], v.size[2]};
  const std::int64_t stride[3] = {1, n[0], n[0] * n[1]};
  std::vector<float> line, out;
  for (int a = 0; a < 3; ++a) {
    const int b = (a + 1) % 3, c = (a + 2) % 3;
    line.resize(n[a]);
    out.resize(n[a]);
    for (std::int64_t q = 0; q < n[c]; ++q) {
      for (std::int64_t p = 0; p < n[b]; ++p) {
        const std::int64_t base = p * stride[b] + q * stride[c];
        for (std::int64_t t = 0; t < n[a]; ++t) line[t] = v.values[base + t * stride[a]];
        for (std::int64_t t = 0; t < n[a]; ++t) {
          double acc = 0;
          for (int d = -r; d <= r; ++d) acc += kernel[d + r] * line[std::clamp<std::int64_t>(t + d, 0, n[a] - 1)];
          out[t] = static_cast<float>(acc);
        }
        for (std::int64_t t = 0; t < n[a]; ++t) v.values[base + t * stride[a]] = out[t];
      }
    }
  }
}

}  // namespace grainlab::ct
