// SH grains (see sh_grain.h).
//
// Meshing: the unit sphere is sampled at faces / 2 + 2 Fibonacci directions
// and triangulated as their convex hull (rounded_hull_mesh of a point and a
// unit ball: exactly `faces` outward triangles, near-equilateral). Each
// vertex u goes to r(u) u.
//
// Why r > 0 is the whole check. A triangle a = r_a u_a, b = r_b u_b,
// c = r_c u_c has the normal n = (b - a) x (c - a) = a x b + b x c + c x a,
// whose radial component at its centre is
//   n . (a + b + c) = 3 det(a, b, c) = 3 r_a r_b r_c det(u_a, u_b, u_c),
// and det(u_a, u_b, u_c) > 0 for every outward triangle of the sphere's
// mesh. So with r > 0 at the vertices every triangle faces outward, each
// lies inside the cone of its spherical triangle, and the cones tile space
// once: the mesh is closed and cannot fold over itself, however fast r
// changes. The exact surface cannot fold either (its normal's radial
// component is r / sqrt(r^2 + |grad r|^2) > 0). What can go wrong is r <= 0,
// also between the vertices, where the mesh would not see it: r is
// therefore also checked on a finer grid (sphere_quadrature of band
// max(2 degree, 60): 7,381 directions at degree 30).
//
// Chords cut inside. Vertices on the surface leave each flat triangle inside
// a convex surface by the sag g(x), which vanishes at its corners; for a
// surface curved alike in all directions g is a quadratic, kappa (R_c^2 -
// |x - O|^2) about the triangle's circumcentre O, and its mean over any
// triangle is 3/4 of its value at the centroid (the triangle's polar moment
// about its centroid is A (a^2 + b^2 + c^2) / 36 and R_c^2 - |OG|^2 =
// (a^2 + b^2 + c^2) / 9). A sphere meshed that way at 2000 faces is 0.57 %
// short in volume. So each vertex is moved out along its ray by 3/4 of the
// area-weighted mean sag of its triangles at their centroids (measured: r at
// the centroid's direction less the triangle's distance along it; negative,
// an inward move, where the surface is concave), at most 10 % of its radius:
// the facets then cut through the surface and the mesh's volume and area are
// unbiased to second order (a sphere at 2000 faces: volume -0.57 % -> -0.001 %,
// area +0.07 %; docs/grains.md;
// tests/grains/sh_grain_test.cpp). All radii stay positive, so the proof
// above still holds.

#include "grains/sh_grain.h"

#include "core/atomic_file.h"
#include "core/bounded_read.h"
#include "core/error.h"
#include "geometry/mass_properties.h"
#include "geometry/rounded_hull.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <map>
#include <numbers>
#include <sstream>

namespace grainlab {
namespace {

constexpr int kMaxDegree = 200;

// The blank-separated numbers of one line, or false when a token is not a
// number or there are more or fewer than `count`.
bool parse_numbers(const std::string& line, int count, std::vector<double>& out) {
  out.clear();
  const char* p = line.c_str();
  while (true) {
    while (*p && std::isspace(static_cast<unsigned char>(*p))) ++p;
    if (!*p) break;
    char* end = nullptr;
    const double v = std::strtod(p, &end);
    if (end == p || (*end && !std::isspace(static_cast<unsigned char>(*end)))) return false;
    out.push_back(v);
    p = end;
  }
  return static_cast<int>(out.size()) == count;
}

double degrees(double radians) { return radians * 180 / std::numbers::pi; }

// r(u), or InputError naming the grain and the direction where r <= 0.
double check_positive(const ShCoefficients& c, const Vec3& u, const std::string& name) {
  const double r = sh_radius(c, u);
  if (!(r > 0)) {
    input_error("{}: the radius is {:.6g} (not positive) towards theta = {:.2f} deg, phi = {:.2f} deg; an SH "
                "grain must be star-shaped about its origin with r > 0 in every direction (a wrong or corrupt "
                "coefficient?)",
                name, r, degrees(polar_angle(u)), degrees(azimuth(u)));
  }
  return r;
}

}  // namespace

bool is_sh_file(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  for (char& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return ext == kShExtension;
}

ShCoefficients read_sh_file(const std::filesystem::path& path) {
  const std::string file = path.string();
  // Degree 200, the most read, is 40,401 lines of about 48 bytes.
  const std::string text = read_bounded_file(path, 16 * kMiB, "spherical-harmonic file");
  const bool ends_with_newline = !text.empty() && text.back() == '\n';

  std::map<std::pair<int, int>, std::pair<std::complex<double>, int>> seen;  // (n, m) -> value, line
  std::istringstream lines(text);
  std::string line;
  std::vector<double> v;
  int line_no = 0, max_n = -1;
  while (std::getline(lines, line)) {
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.find_first_not_of(" \t") == std::string::npos) continue;
    if (!parse_numbers(line, 4, v)) {
      const bool last = lines.peek() == EOF;
      input_error("{}:{}: expected four numbers `n m Re(a_nm) Im(a_nm)`, got '{}'{}", file, line_no,
                  line.size() > 80 ? line.substr(0, 80) + "..." : line,
                  last && !ends_with_newline ? " (the last line, without its end: is the file truncated?)" : "");
    }
    const double n = v[0], m = v[1];
    if (n != std::floor(n) || m != std::floor(m) || n < 0 || n > kMaxDegree || std::abs(m) > n) {
      input_error("{}:{}: (n, m) = ({}, {}) is not a degree and order: n must be an integer in 0..{} and m an "
                  "integer with |m| <= n",
                  file, line_no, v[0], v[1], kMaxDegree);
    }
    if (!std::isfinite(v[2]) || !std::isfinite(v[3])) {
      input_error("{}:{}: a_nm for (n, m) = ({}, {}) is not a finite number ('{}')", file, line_no, n, m, line);
    }
    const auto key = std::make_pair(static_cast<int>(n), static_cast<int>(m));
    if (const auto it = seen.find(key); it != seen.end()) {
      input_error("{}:{}: (n, m) = ({}, {}) is given twice, here and on line {}; each coefficient must appear once",
                  file, line_no, key.first, key.second, it->second.second);
    }
    seen.emplace(key, std::make_pair(std::complex<double>(v[2], v[3]), line_no));
    max_n = std::max(max_n, key.first);
  }
  if (max_n < 0) input_error("{}: holds no coefficient line `n m Re(a_nm) Im(a_nm)`", file);

  ShCoefficients c(max_n);
  for (int n = 0; n <= max_n; ++n) {
    for (int m = n; m >= -n; --m) {
      const auto it = seen.find({n, m});
      if (it == seen.end()) {
        input_error("{}: no line for (n, m) = ({}, {}): a file of degree {} has {} lines, one for each (n, m) with "
                    "|m| <= n, and this one has {} (truncated or incomplete?)",
                    file, n, m, max_n, sh_count(max_n), seen.size());
      }
      c.at(n, m) = it->second.first;
    }
  }
  if (!(c.at(0, 0).real() > 0)) {
    input_error("{}: a_00 = {} must be positive (it is sqrt(4 pi) times the mean radius)", file,
                c.at(0, 0).real());
  }
  return c;
}

void write_sh_file(const ShCoefficients& c, const std::filesystem::path& path) {
  std::string text;
  for (int n = 0; n <= c.degree; ++n) {
    for (int m = n; m >= -n; --m) {
      text += fmt::format("{:4d}{:4d}{:20.10f}{:20.10f}\n", n, m, c.at(n, m).real(), c.at(n, m).imag());
    }
  }
  write_file_atomically(path, text);
}

TriMesh sh_mesh(const ShCoefficients& c, int faces, const std::string& name) {
  if (faces < 8) input_error("{}: a grain mesh needs at least 8 faces, asked for {}", name, faces);
  const std::vector<Vec3> centre = {Vec3::Zero()};
  TriMesh m = rounded_hull_mesh(centre, 1.0, faces);
  for (Vec3& v : m.vertices) {
    const Vec3 u = v.normalized();
    v = check_positive(c, u, name) * u;
  }
  // The chords' sag (see the top of this file).
  std::vector<double> sag(m.vertices.size(), 0), weight(m.vertices.size(), 0);
  for (const Face& f : m.faces) {
    const Vec3 &a = m.vertices[f[0]], &b = m.vertices[f[1]], &cc = m.vertices[f[2]];
    const Vec3 n = (b - a).cross(cc - a);
    const Vec3 u = (a + b + cc).normalized();
    const double g = sh_radius(c, u) - n.dot(a) / n.dot(u);
    const double area = 0.5 * n.norm();
    for (const Index i : f) {
      sag[i] += area * g;
      weight[i] += area;
    }
  }
  for (std::size_t i = 0; i < m.vertices.size(); ++i) {
    const double r = m.vertices[i].norm();
    const double move = std::clamp(0.75 * sag[i] / weight[i], -0.1 * r, 0.1 * r);
    m.vertices[i] *= (r + move) / r;
  }
  // Between the vertices too (see the top of this file).
  const SphereQuadrature grid = sphere_quadrature(std::max(2 * c.degree, 60));
  const std::vector<double> radii = sh_radii(c, grid);
  for (std::size_t i = 0; i < radii.size(); ++i) {
    if (!(radii[i] > 0)) check_positive(c, grid.directions[i], name);  // says where
  }
  return m;
}

ShCoefficients truncated(const ShCoefficients& c, int degree) {
  if (degree < 0 || degree >= c.degree) return c;
  ShCoefficients out(degree);
  std::copy(c.a.begin(), c.a.begin() + sh_count(degree), out.a.begin());
  return out;
}

TriMesh load_sh_grain(const std::filesystem::path& path, int faces, const ShOptions& scale) {
  TriMesh m = sh_mesh(truncated(read_sh_file(path), scale.max_degree), faces, path.string());
  double s = scale.unit;
  if (scale.d_eq > 0) {
    const double volume = mass_properties(m).volume;
    s = scale.d_eq / std::cbrt(6 * volume / std::numbers::pi);
  }
  if (!(s > 0) || !std::isfinite(s)) {
    input_error("{}: the scale to metres must be positive and finite, got unit {} and d_eq {}", path.string(),
                scale.unit, scale.d_eq);
  }
  for (Vec3& v : m.vertices) v *= s;
  return m;
}

}  // namespace grainlab
