// Closed, outward triangle meshes of simple solids.
//
// The icosahedron's 12 vertices are the cyclic permutations of (0, +-1, +-phi),
// phi = (1 + sqrt 5) / 2, normalised to the unit sphere. Each subdivision
// splits a triangle into four through its edge midpoints (shared between the
// two faces of an edge through a cache keyed by the edge) and pushes the new
// vertices out to the sphere; children keep their parent's winding, so the
// result stays outward.
#include "geometry/primitives.h"

#include "core/error.h"

#include <cmath>
#include <map>
#include <utility>

namespace grainlab {

TriMesh box_mesh(double hx, double hy, double hz) {
  if (!(hx > 0 && hy > 0 && hz > 0) || !std::isfinite(hx + hy + hz)) {
    input_error("box_mesh: half extents must be positive and finite, got ({}, {}, {})", hx, hy, hz);
  }
  TriMesh m;
  // Vertex i has x sign from bit 0, y from bit 1, z from bit 2.
  for (int i = 0; i < 8; ++i) {
    m.vertices.emplace_back((i & 1) ? hx : -hx, (i & 2) ? hy : -hy, (i & 4) ? hz : -hz);
  }
  // Two triangles per side, counter-clockwise seen from outside.
  m.faces = {{0, 2, 3}, {0, 3, 1},   // z = -hz
             {4, 5, 7}, {4, 7, 6},   // z = +hz
             {0, 1, 5}, {0, 5, 4},   // y = -hy
             {2, 6, 7}, {2, 7, 3},   // y = +hy
             {0, 4, 6}, {0, 6, 2},   // x = -hx
             {1, 3, 7}, {1, 7, 5}};  // x = +hx
  return m;
}

TriMesh tetrahedron_mesh(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const double six_v = (b - a).dot((c - a).cross(d - a));
  const double scale = std::max({(b - a).norm(), (c - a).norm(), (d - a).norm()});
  if (!std::isfinite(six_v) || std::abs(six_v) <= 1e-12 * scale * scale * scale) {
    input_error("tetrahedron_mesh: the four corners are coplanar or non-finite");
  }
  TriMesh m;
  m.vertices = {a, b, c, d};
  // With (b-a).((c-a)x(d-a)) > 0, d lies on the side of (a,b,c)'s normal, so
  // (a,c,b) faces away from d; the other three follow from it.
  m.faces = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  if (six_v < 0) {
    for (Face& f : m.faces) std::swap(f[1], f[2]);
  }
  return m;
}

TriMesh icosphere(double radius, int subdivisions) {
  if (!(radius > 0) || !std::isfinite(radius)) {
    input_error("icosphere: radius must be positive and finite, got {}", radius);
  }
  if (subdivisions < 0 || subdivisions > 8) {
    input_error("icosphere: subdivisions must be in 0..8, got {}", subdivisions);
  }
  const double p = (1.0 + std::sqrt(5.0)) / 2.0;
  TriMesh m;
  m.vertices = {{-1, p, 0}, {1, p, 0}, {-1, -p, 0}, {1, -p, 0},
                {0, -1, p}, {0, 1, p}, {0, -1, -p}, {0, 1, -p},
                {p, 0, -1}, {p, 0, 1}, {-p, 0, -1}, {-p, 0, 1}};
  for (Vec3& v : m.vertices) v.normalize();
  m.faces = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
             {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
             {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
             {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int s = 0; s < subdivisions; ++s) {
    std::map<std::pair<Index, Index>, Index> midpoint;
    auto mid = [&](Index i, Index j) {
      const auto key = std::minmax(i, j);
      auto it = midpoint.find(key);
      if (it != midpoint.end()) return it->second;
      const auto id = static_cast<Index>(m.vertices.size());
      m.vertices.push_back((m.vertices[i] + m.vertices[j]).normalized());
      midpoint.emplace(key, id);
      return id;
    };
    std::vector<Face> next;
    next.reserve(m.faces.size() * 4);
    for (const Face& f : m.faces) {
      const Index ab = mid(f[0], f[1]), bc = mid(f[1], f[2]), ca = mid(f[2], f[0]);
      next.push_back({f[0], ab, ca});
      next.push_back({f[1], bc, ab});
      next.push_back({f[2], ca, bc});
      next.push_back({ab, bc, ca});
    }
    m.faces = std::move(next);
  }
  for (Vec3& v : m.vertices) v *= radius;
  return m;
}

TriMesh ellipsoid_mesh(double a, double b, double c, int subdivisions) {
  if (!(a > 0 && b > 0 && c > 0) || !std::isfinite(a + b + c)) {
    input_error("ellipsoid_mesh: semi-axes must be positive and finite, got ({}, {}, {})", a, b, c);
  }
  TriMesh m = icosphere(1.0, subdivisions);
  for (Vec3& v : m.vertices) v = Vec3(a * v.x(), b * v.y(), c * v.z());
  return m;
}

namespace {

double cross2(const Vec2& a, const Vec2& b, const Vec2& c) {
  return (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
}

// Ear clipping of a simple counter-clockwise polygon: repeatedly cuts off a
// convex corner whose triangle holds no other corner.
std::vector<Face> triangulate(const std::vector<Vec2>& p) {
  std::vector<Index> left(p.size());
  for (std::size_t k = 0; k < p.size(); ++k) left[k] = static_cast<Index>(k);
  std::vector<Face> out;
  while (left.size() > 3) {
    bool cut = false;
    for (std::size_t k = 0; k < left.size() && !cut; ++k) {
      const Index a = left[(k + left.size() - 1) % left.size()], b = left[k], c = left[(k + 1) % left.size()];
      if (cross2(p[a], p[b], p[c]) <= 0) continue;  // reflex or flat corner
      bool empty = true;
      for (Index q : left)
        if (q != a && q != b && q != c && cross2(p[a], p[b], p[q]) >= 0 && cross2(p[b], p[c], p[q]) >= 0 &&
            cross2(p[c], p[a], p[q]) >= 0)
          empty = false;
      if (!empty) continue;
      out.push_back({a, b, c});
      left.erase(left.begin() + static_cast<std::ptrdiff_t>(k));
      cut = true;
    }
    if (!cut) input_error("prism: the polygon of {} corners is not simple and counter-clockwise", p.size());
  }
  if (cross2(p[left[0]], p[left[1]], p[left[2]]) <= 0)
    input_error("prism: the polygon of {} corners is not simple and counter-clockwise", p.size());
  out.push_back({left[0], left[1], left[2]});
  return out;
}

}  // namespace

TriMesh prism_mesh(const std::vector<Vec2>& polygon, double half_depth) {
  if (polygon.size() < 3) input_error("prism: the polygon has {} corners; give at least 3", polygon.size());
  if (!(half_depth > 0)) input_error("prism: half depth {} must be positive", half_depth);
  const Index n = static_cast<Index>(polygon.size());
  TriMesh m;
  for (const Vec2& q : polygon) m.vertices.emplace_back(q.x(), q.y(), -half_depth);  // bottom: 0..n-1
  for (const Vec2& q : polygon) m.vertices.emplace_back(q.x(), q.y(), half_depth);   // top: n..2n-1
  for (const Face& f : triangulate(polygon)) {
    m.faces.push_back({f[0] + n, f[1] + n, f[2] + n});  // top, seen from +z: counter-clockwise
    m.faces.push_back({f[0], f[2], f[1]});              // bottom, reversed
  }
  for (Index k = 0; k < n; ++k) {  // sides: outward for a counter-clockwise outline
    const Index j = (k + 1) % n;
    m.faces.push_back({k, j, j + n});
    m.faces.push_back({k, j + n, k + n});
  }
  return m;
}

}  // namespace grainlab
