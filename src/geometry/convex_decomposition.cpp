// Convex decomposition by greedy plane cuts (see convex_decomposition.h for
// the method and why the pieces cover the mesh).
//
// A part carries the mesh's surface clipped to its cell (polygons) and the
// voxel centres of the mesh inside the cell. Cutting by the plane n.p = c
// splits each polygon in two (Sutherland-Hodgman) and the voxels by side;
// the hull of each side's polygon vertices is that side's piece. A point
// where an edge crosses the plane is computed from the edge's endpoints in
// a fixed order, so the polygons on both sides of an edge share it bit for
// bit and duplicates can be dropped exactly.
#include "geometry/convex_decomposition.h"

#include "core/error.h"
#include "geometry/convex_hull.h"
#include "geometry/mass_properties.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <unordered_set>

namespace grainlab {

namespace {

using Polygon = std::vector<Vec3>;

struct Part {
  std::vector<Polygon> polys;  // the surface inside the part's cell
  std::vector<int> cells;      // voxel centres inside the mesh and the cell
  std::vector<HalfSpace> planes;  // the cell's bounding planes
  std::vector<Vec3> corners;   // corners of the cell inside the mesh (three planes meet there)
  double hull_volume = 0;
  bool final = false;
};

struct Cut {
  Vec3 n = Vec3::UnitX();
  double c = 0;
  double cost = std::numeric_limits<double>::infinity();  // V(hull left) + V(hull right)
};

// Hull volume of a point set; 0 when it has no interior (or too few points).
double hull_volume(const std::vector<Vec3>& pts) {
  if (pts.size() < 4) return 0;
  try {
    const ConvexHull h = convex_hull(pts);
    double six_v = 0;
    const Vec3& o = h.vertices[0];
    for (const Face& f : h.faces)
      six_v += (h.vertices[f[0]] - o).dot((h.vertices[f[1]] - o).cross(h.vertices[f[2]] - o));
    return six_v / 6;
  } catch (const InputError&) {
    return 0;  // coplanar: a flat sliver
  }
}

// The crossing of segment ab with the plane, from the endpoints in a fixed
// (lexicographic) order so that both polygons sharing the edge get the same bits.
Vec3 crossing(Vec3 a, Vec3 b, const Vec3& n, double c) {
  if (std::lexicographical_compare(b.data(), b.data() + 3, a.data(), a.data() + 3)) std::swap(a, b);
  const double da = n.dot(a) - c, db = n.dot(b) - c;
  return a + (da / (da - db)) * (b - a);
}

// Splits a convex or non-convex planar polygon by n.p = c into its parts
// with n.p <= c (left) and n.p > c (right).
void split_polygon(const Polygon& p, const Vec3& n, double c, Polygon& left, Polygon& right) {
  left.clear();
  right.clear();
  const std::size_t m = p.size();
  for (std::size_t i = 0; i < m; ++i) {
    const Vec3& a = p[i];
    const Vec3& b = p[(i + 1) % m];
    const bool a_left = n.dot(a) <= c, b_left = n.dot(b) <= c;
    (a_left ? left : right).push_back(a);
    if (a_left != b_left) {
      const Vec3 x = crossing(a, b, n, c);
      left.push_back(x);
      right.push_back(x);
    }
  }
}

struct Vec3Hash {
  std::size_t operator()(const Vec3& v) const {
    std::size_t h = 0;
    for (int k = 0; k < 3; ++k) h = h * 1000003u ^ std::hash<double>()(v[k]);
    return h;
  }
};

// The distinct vertices of a set of polygons.
std::vector<Vec3> distinct_points(const std::vector<Polygon>& polys) {
  std::unordered_set<Vec3, Vec3Hash> seen;
  std::vector<Vec3> out;
  for (const Polygon& p : polys)
    for (const Vec3& v : p)
      if (seen.insert(v).second) out.push_back(v);
  return out;
}

// The points whose hull is the part: its surface's vertices and its cell's
// corners inside the mesh (the caps' other vertices lie on the surface).
std::vector<Vec3> part_points(const Part& part) {
  std::vector<Vec3> out = distinct_points(part.polys);
  out.insert(out.end(), part.corners.begin(), part.corners.end());
  return out;
}

// True if p is inside the closed mesh: its winding number (the solid angle
// of every face seen from p, Van Oosterom and Strackee's formula) is 1, not 0.
bool inside_mesh(const TriMesh& mesh, const Vec3& p) {
  double omega = 0;
  for (const Face& f : mesh.faces) {
    const Vec3 a = mesh.vertices[f[0]] - p, b = mesh.vertices[f[1]] - p, c = mesh.vertices[f[2]] - p;
    const double la = a.norm(), lb = b.norm(), lc = c.norm();
    omega += 2 * std::atan2(a.dot(b.cross(c)), la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb);
  }
  return omega > 2 * std::numbers::pi;
}

// The two sides' points of a part cut by n.p = c (without splitting it for
// good; the corners the cut itself would make are left out of the estimate).
void side_points(const Part& part, const std::vector<Vec3>& points, const Vec3& n, double c,
                 std::vector<Vec3>& left, std::vector<Vec3>& right) {
  left.clear();
  right.clear();
  for (const Vec3& v : points) (n.dot(v) <= c ? left : right).push_back(v);
  for (const Polygon& p : part.polys) {
    const std::size_t m = p.size();
    for (std::size_t i = 0; i < m; ++i) {
      const Vec3& a = p[i];
      const Vec3& b = p[(i + 1) % m];
      if ((n.dot(a) <= c) != (n.dot(b) <= c)) {
        const Vec3 x = crossing(a, b, n, c);
        left.push_back(x);
        right.push_back(x);
      }
    }
  }
}

// Voxel centres inside the mesh: a ray along z per (x, y) column, filled
// between pairs of crossings. Columns are shifted off the grid by an
// irrational fraction so that no ray meets a vertex or an edge exactly.
std::vector<Vec3> inside_voxels(const TriMesh& mesh, int grid, double& cell) {
  Vec3 lo = mesh.vertices[0], hi = lo;
  for (const Vec3& v : mesh.vertices) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  cell = (hi - lo).maxCoeff() / grid;
  const int nx = static_cast<int>(std::ceil((hi.x() - lo.x()) / cell)) + 1;
  const int ny = static_cast<int>(std::ceil((hi.y() - lo.y()) / cell)) + 1;
  const Vec3 origin = lo + cell * Vec3(0.5 - 0.0123456789, 0.5 - 0.0234567891, 0.5);
  std::vector<std::vector<double>> hits(static_cast<std::size_t>(nx) * ny);
  for (const Face& f : mesh.faces) {
    const Vec3& a = mesh.vertices[f[0]];
    const Vec3& b = mesh.vertices[f[1]];
    const Vec3& c = mesh.vertices[f[2]];
    const double det = (b.x() - a.x()) * (c.y() - a.y()) - (c.x() - a.x()) * (b.y() - a.y());
    if (det == 0) continue;  // seen edge-on from the rays
    const int i0 = std::max(0, static_cast<int>(std::floor((std::min({a.x(), b.x(), c.x()}) - origin.x()) / cell)));
    const int i1 = std::min(nx - 1, static_cast<int>(std::ceil((std::max({a.x(), b.x(), c.x()}) - origin.x()) / cell)));
    const int j0 = std::max(0, static_cast<int>(std::floor((std::min({a.y(), b.y(), c.y()}) - origin.y()) / cell)));
    const int j1 = std::min(ny - 1, static_cast<int>(std::ceil((std::max({a.y(), b.y(), c.y()}) - origin.y()) / cell)));
    for (int i = i0; i <= i1; ++i)
      for (int j = j0; j <= j1; ++j) {
        const double x = origin.x() + i * cell, y = origin.y() + j * cell;
        // Barycentric weights of (x, y) in the projected triangle.
        const double u = ((b.x() - x) * (c.y() - y) - (c.x() - x) * (b.y() - y)) / det;
        const double v = ((c.x() - x) * (a.y() - y) - (a.x() - x) * (c.y() - y)) / det;
        const double w = 1 - u - v;
        if (u < 0 || v < 0 || w < 0) continue;
        hits[static_cast<std::size_t>(i) * ny + j].push_back(u * a.z() + v * b.z() + w * c.z());
      }
  }
  std::vector<Vec3> out;
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j) {
      std::vector<double>& z = hits[static_cast<std::size_t>(i) * ny + j];
      if (z.size() % 2 != 0) continue;  // a grazing ray: leave the column out
      std::sort(z.begin(), z.end());
      for (std::size_t k = 0; k + 1 < z.size(); k += 2) {
        const int k0 = static_cast<int>(std::ceil((z[k] - origin.z()) / cell));
        const int k1 = static_cast<int>(std::floor((z[k + 1] - origin.z()) / cell));
        for (int kz = k0; kz <= k1; ++kz)
          out.emplace_back(origin.x() + i * cell, origin.y() + j * cell, origin.z() + kz * cell);
      }
    }
  return out;
}

// Principal directions of a part's voxels, and their pairwise diagonals.
std::vector<Vec3> cut_directions(const Part& part, const std::vector<Vec3>& voxels) {
  Vec3 mean = Vec3::Zero();
  for (int k : part.cells) mean += voxels[k];
  mean /= static_cast<double>(part.cells.size());
  Mat3 cov = Mat3::Zero();
  for (int k : part.cells) {
    const Vec3 d = voxels[k] - mean;
    cov += d * d.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Mat3> eig(cov);
  const Mat3 a = eig.eigenvectors();
  std::vector<Vec3> dirs{a.col(0), a.col(1), a.col(2)};
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j) {
      dirs.push_back((a.col(i) + a.col(j)).normalized());
      dirs.push_back((a.col(i) - a.col(j)).normalized());
    }
  return dirs;
}

// The best cut of a part: coarse offsets along each direction, then a
// ternary search around the best one. Sides with less than min_volume of
// voxels are not allowed (no slivers).
Cut best_cut(const Part& part, const std::vector<Vec3>& voxels, double voxel_volume, double min_volume) {
  const std::vector<Vec3> points = part_points(part);
  std::vector<Vec3> left, right;
  auto cost_of = [&](const Vec3& n, double c) {
    std::size_t n_left = 0;
    for (int k : part.cells) n_left += n.dot(voxels[k]) <= c;
    const double v_left = voxel_volume * n_left, v_right = voxel_volume * (part.cells.size() - n_left);
    if (v_left < min_volume || v_right < min_volume) return std::numeric_limits<double>::infinity();
    side_points(part, points, n, c, left, right);
    const double hl = hull_volume(left), hr = hull_volume(right);
    if (hl <= 0 || hr <= 0) return std::numeric_limits<double>::infinity();
    return hl + hr;
  };
  constexpr int kOffsets = 10;
  Cut best;
  for (const Vec3& n : cut_directions(part, voxels)) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const Vec3& p : points) {
      lo = std::min(lo, n.dot(p));
      hi = std::max(hi, n.dot(p));
    }
    const double step = (hi - lo) / (kOffsets + 1);
    double best_here = std::numeric_limits<double>::infinity();
    int k_best = -1;
    for (int k = 1; k <= kOffsets; ++k) {
      const double cost = cost_of(n, lo + k * step);
      if (cost < best_here) {
        best_here = cost;
        k_best = k;
      }
    }
    if (k_best < 0) continue;
    // Ternary search over the neighbouring interval.
    double a = lo + (k_best - 1) * step, b = lo + (k_best + 1) * step;
    for (int it = 0; it < 5; ++it) {
      const double m1 = a + (b - a) / 3, m2 = b - (b - a) / 3;
      if (cost_of(n, m1) <= cost_of(n, m2)) b = m2; else a = m1;
    }
    const double c_refined = 0.5 * (a + b);
    const double cost_refined = cost_of(n, c_refined);
    const double c = cost_refined < best_here ? c_refined : lo + k_best * step;
    const double cost = std::min(cost_refined, best_here);
    if (cost < best.cost) best = {n, c, cost};
  }
  return best;
}

}  // namespace

ConvexDecomposition decompose_convex(const TriMesh& mesh, const DecompositionOptions& options) {
  if (options.max_pieces < 1) input_error("convex decomposition: max_pieces {} must be at least 1", options.max_pieces);
  if (!(options.tolerance >= 0)) input_error("convex decomposition: tolerance {} must be >= 0", options.tolerance);
  if (options.grid < 8) input_error("convex decomposition: grid {} must be at least 8 voxels", options.grid);
  ConvexDecomposition out;
  out.volume = mass_properties(mesh).volume;
  if (!(out.volume > 0)) input_error("convex decomposition: the mesh has no volume (is it closed and outward?)");

  Part root;
  Vec3 lo = mesh.vertices[0], hi = lo;
  for (const Vec3& v : mesh.vertices) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  const double scale = (hi - lo).norm();
  for (const Face& f : mesh.faces) root.polys.push_back({mesh.vertices[f[0]], mesh.vertices[f[1]], mesh.vertices[f[2]]});
  root.hull_volume = out.hull_volume = hull_volume(mesh.vertices);
  std::vector<Part> parts;
  // Splitting only pays where the hull exceeds the mesh.
  if (out.hull_volume - out.volume > options.tolerance * out.volume && options.max_pieces > 1) {
    double cell = 0;
    const std::vector<Vec3> voxels = inside_voxels(mesh, options.grid, cell);
    // Each voxel stands for an equal share of the exact volume.
    const double voxel_volume = voxels.empty() ? 0 : out.volume / static_cast<double>(voxels.size());
    for (int k = 0; k < static_cast<int>(voxels.size()); ++k) root.cells.push_back(k);
    parts.push_back(std::move(root));
    const double min_volume = 0.02 * out.volume;   // no piece smaller than 2 % of the grain
    const double min_gain = 0.002 * out.volume;    // a cut must fill at least 0.2 % less of the dents
    while (static_cast<int>(parts.size()) < options.max_pieces) {
      double total_excess = 0, worst = 0;
      int w = -1;
      for (int k = 0; k < static_cast<int>(parts.size()); ++k) {
        const double excess = parts[k].hull_volume - voxel_volume * static_cast<double>(parts[k].cells.size());
        total_excess += std::max(excess, 0.0);
        if (!parts[k].final && excess > worst) {
          worst = excess;
          w = k;
        }
      }
      if (w < 0 || total_excess <= options.tolerance * out.volume) break;
      Part& p = parts[w];
      const Cut cut = best_cut(p, voxels, voxel_volume, min_volume);
      if (!(p.hull_volume - cut.cost > min_gain)) {
        p.final = true;
        continue;
      }
      Part l, r;
      Polygon pl, pr;
      for (const Polygon& poly : p.polys) {
        split_polygon(poly, cut.n, cut.c, pl, pr);
        if (pl.size() >= 3) l.polys.push_back(pl);
        if (pr.size() >= 3) r.polys.push_back(pr);
      }
      for (int k : p.cells) (cut.n.dot(voxels[k]) <= cut.c ? l.cells : r.cells).push_back(k);
      for (const Vec3& x : p.corners) (cut.n.dot(x) <= cut.c ? l.corners : r.corners).push_back(x);
      // New corners: where the cut meets two of the cell's planes inside the cell and the mesh.
      const double eps = 1e-9 * scale;
      for (std::size_t i = 0; i < p.planes.size(); ++i)
        for (std::size_t j = i + 1; j < p.planes.size(); ++j) {
          Mat3 a;
          a.row(0) = p.planes[i].n;
          a.row(1) = p.planes[j].n;
          a.row(2) = cut.n;
          if (std::abs(a.determinant()) < 1e-6) continue;
          const Vec3 x = a.inverse() * Vec3(p.planes[i].c, p.planes[j].c, cut.c);
          bool in_cell = true;
          for (const HalfSpace& q : p.planes) in_cell = in_cell && q.n.dot(x) <= q.c + eps;
          if (in_cell && inside_mesh(mesh, x)) {
            l.corners.push_back(x);
            r.corners.push_back(x);
          }
        }
      l.planes = r.planes = p.planes;
      l.planes.push_back({cut.n, cut.c});
      r.planes.push_back({-cut.n, -cut.c});
      l.hull_volume = hull_volume(part_points(l));
      r.hull_volume = hull_volume(part_points(r));
      p = std::move(l);
      parts.push_back(std::move(r));
    }
  } else {
    parts.push_back(std::move(root));
  }
  for (const Part& p : parts) {
    out.pieces.push_back(parts.size() == 1 ? mesh.vertices : part_points(p));
    out.cells.push_back(p.planes);
    out.pieces_volume += p.hull_volume;
  }
  return out;
}

}  // namespace grainlab
