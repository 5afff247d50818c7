// Shape metrics (see shape_metrics.h).
//
// Wadell roundness after Zheng & Hryciw (2015, 2016). On each outline:
//  1. r_in: the largest inscribed circle, maximising the signed distance to the
//     outline (grid search, then pattern search; the distance is concave
//     inside a convex outline, so the search finds the global maximum there).
//  2. Resample the outline to kSamples points evenly spaced in arc length h.
//  3. Smooth it with a Gaussian of kCornerScale r_in in arc length: this removes
//     facet kinks and pixel staircases, leaving features larger than that scale.
//  4. Local curvature radius rho_i: the circle through the smoothed points
//     i - m, i, i + m (m h ~ kCornerScale r_in), signed so that convex turns
//     (left turns on a counter-clockwise outline) are positive.
//  5. Corners: maximal runs of convex points with rho_i < r_in ("the outline
//     curves more sharply than the inscribed circle"). A circle is fitted to
//     each run by least squares (Kasa's algebraic fit) and capped at r_in.
//  6. R = mean corner radius / r_in, capped at 1; an outline with no corner
//     (a circle, up to noise) has R = 1.
// The smoothing scale sets a floor: a knife-sharp corner reads as a radius of
// about kCornerScale r_in (R ~ 0.05 for a cube), much as pixel size limits the
// image-based method.
#include "geometry/shape_metrics.h"

#include "core/error.h"
#include "geometry/convex_hull.h"
#include "geometry/mass_properties.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace grainlab {
namespace {

constexpr int kSamples = 720;           // outline points after resampling
constexpr double kCornerScale = 0.06;   // smoothing and curvature scale, fraction of r_in
constexpr double kConvexLimit = 0.99;   // convexity above which the hull outline is used

double cross2(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

double signed_area(std::span<const Vec2> poly) {
  double a = 0;
  for (std::size_t i = 0, n = poly.size(); i < n; ++i) a += cross2(poly[i], poly[(i + 1) % n]);
  return 0.5 * a;
}

// Distance from p to segment ab.
double segment_distance(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (p - (a + t * ab)).norm();
}

// Positive inside the polygon (distance to the boundary), negative outside.
double signed_distance(std::span<const Vec2> poly, const Vec2& p) {
  double d = std::numeric_limits<double>::infinity();
  bool inside = false;
  for (std::size_t i = 0, n = poly.size(), j = n - 1; i < n; j = i++) {
    const Vec2& a = poly[j];
    const Vec2& b = poly[i];
    d = std::min(d, segment_distance(p, a, b));
    if ((a.y() > p.y()) != (b.y() > p.y()) &&
        p.x() < a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y())) {
      inside = !inside;
    }
  }
  return inside ? d : -d;
}

// Points evenly spaced in arc length around a closed polygon.
std::vector<Vec2> resample(std::span<const Vec2> poly, int n, double* spacing) {
  const std::size_t k = poly.size();
  std::vector<double> cum(k + 1, 0.0);
  for (std::size_t i = 0; i < k; ++i) cum[i + 1] = cum[i] + (poly[(i + 1) % k] - poly[i]).norm();
  const double perimeter = cum[k];
  *spacing = perimeter / n;
  std::vector<Vec2> out;
  out.reserve(static_cast<std::size_t>(n));
  std::size_t seg = 0;
  for (int s = 0; s < n; ++s) {
    const double t = s * *spacing;
    while (seg + 1 < k && cum[seg + 1] <= t) ++seg;
    const double len = cum[seg + 1] - cum[seg];
    const double f = len > 0 ? (t - cum[seg]) / len : 0.0;
    out.push_back(poly[seg] + f * (poly[(seg + 1) % k] - poly[seg]));
  }
  return out;
}

// Cyclic Gaussian smoothing with standard deviation sigma (in samples).
std::vector<Vec2> smooth(const std::vector<Vec2>& p, double sigma) {
  const int n = static_cast<int>(p.size());
  const int half = std::min(n / 2 - 1, static_cast<int>(std::ceil(3 * sigma)));
  if (sigma <= 0 || half < 1) return p;
  std::vector<double> w(static_cast<std::size_t>(half) + 1);
  double total = 0;
  for (int k = 0; k <= half; ++k) {
    w[k] = std::exp(-0.5 * k * k / (sigma * sigma));
    total += k == 0 ? w[k] : 2 * w[k];
  }
  std::vector<Vec2> out(p.size(), Vec2::Zero());
  for (int i = 0; i < n; ++i) {
    Vec2 s = w[0] * p[i];
    for (int k = 1; k <= half; ++k) s += w[k] * (p[(i + k) % n] + p[(i - k + n) % n]);
    out[i] = s / total;
  }
  return out;
}

// Least-squares circle through points (Kasa): minimises sum (|x - c|^2 - r^2)^2.
double fit_circle_radius(const std::vector<Vec2>& pts) {
  Vec2 mean = Vec2::Zero();
  for (const Vec2& p : pts) mean += p;
  mean /= static_cast<double>(pts.size());
  // Unknowns (cx, cy, k) with |x|^2 = 2 c . x + k, x relative to the mean.
  Eigen::Matrix3d ata = Eigen::Matrix3d::Zero();
  Eigen::Vector3d atb = Eigen::Vector3d::Zero();
  for (const Vec2& q : pts) {
    const Vec2 x = q - mean;
    const Eigen::Vector3d row(2 * x.x(), 2 * x.y(), 1.0);
    ata += row * row.transpose();
    atb += row * x.squaredNorm();
  }
  const Eigen::Vector3d sol = ata.ldlt().solve(atb);
  const double r2 = sol.z() + sol.x() * sol.x() + sol.y() * sol.y();
  return (std::isfinite(r2) && r2 > 0) ? std::sqrt(r2) : std::numeric_limits<double>::infinity();
}

}  // namespace

std::vector<Vec2> convex_outline(std::span<const Vec2> points) {
  std::vector<Vec2> p(points.begin(), points.end());
  std::sort(p.begin(), p.end(), [](const Vec2& a, const Vec2& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  p.erase(std::unique(p.begin(), p.end()), p.end());
  if (p.size() < 3) return p;
  std::vector<Vec2> h(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {  // lower chain
    while (k >= 2 && cross2(h[k - 1] - h[k - 2], p[i] - h[k - 2]) <= 0) --k;
    h[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, t = k + 1; i-- > 0;) {  // upper chain
    while (k >= t && cross2(h[k - 1] - h[k - 2], p[i] - h[k - 2]) <= 0) --k;
    h[k++] = p[i];
  }
  h.resize(k - 1);
  return h;
}

std::vector<Vec2> silhouette_outline(std::span<const Vec2> points, std::span<const Face> faces,
                                     int resolution) {
  if (points.empty() || faces.empty()) return {};
  Vec2 lo = points[0], hi = points[0];
  for (const Vec2& p : points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const int res = std::max(16, resolution);
  const double pixel = std::max(hi.x() - lo.x(), hi.y() - lo.y()) / (res - 4);
  if (!(pixel > 0)) return {};
  const Vec2 origin = lo - Vec2(2 * pixel, 2 * pixel);
  const int nx = static_cast<int>(std::ceil((hi.x() - origin.x()) / pixel)) + 2;
  const int ny = static_cast<int>(std::ceil((hi.y() - origin.y()) / pixel)) + 2;
  // Coverage of each pixel: the fraction of its kSub x kSub sample points that
  // lie in a projected triangle (either winding).
  constexpr int kSub = 4;
  const int sx = nx * kSub, sy = ny * kSub;
  const double sample = pixel / kSub;
  std::vector<unsigned char> in(static_cast<std::size_t>(sx) * sy, 0);
  for (const Face& f : faces) {
    const Vec2 v[3] = {(points[f[0]] - origin) / sample, (points[f[1]] - origin) / sample,
                       (points[f[2]] - origin) / sample};
    if (cross2(v[1] - v[0], v[2] - v[0]) == 0) continue;
    // Scanline fill: on each sample row, the samples between the triangle's edges.
    const double ylo = std::min({v[0].y(), v[1].y(), v[2].y()}), yhi = std::max({v[0].y(), v[1].y(), v[2].y()});
    const int y0 = std::max(0, static_cast<int>(std::ceil(ylo - 0.5)));
    const int y1 = std::min(sy - 1, static_cast<int>(std::floor(yhi - 0.5)));
    for (int y = y0; y <= y1; ++y) {
      const double yc = y + 0.5;
      double xl = std::numeric_limits<double>::infinity(), xr = -xl;
      for (int k = 0; k < 3; ++k) {
        const Vec2& a = v[k];
        const Vec2& b = v[(k + 1) % 3];
        if (a.y() == b.y() || yc < std::min(a.y(), b.y()) || yc > std::max(a.y(), b.y())) continue;
        const double x = a.x() + (yc - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
        xl = std::min(xl, x);
        xr = std::max(xr, x);
      }
      const int x0 = std::max(0, static_cast<int>(std::ceil(xl - 0.5)));
      const int x1 = std::min(sx - 1, static_cast<int>(std::floor(xr - 0.5)));
      if (x0 <= x1) std::fill_n(in.begin() + static_cast<std::ptrdiff_t>(y) * sx + x0, x1 - x0 + 1, 1);
    }
  }
  std::vector<double> cover(static_cast<std::size_t>(nx) * ny, 0.0);
  for (int y = 0; y < sy; ++y) {
    for (int x = 0; x < sx; ++x) {
      cover[static_cast<std::size_t>(y / kSub) * nx + x / kSub] += in[static_cast<std::size_t>(y) * sx + x];
    }
  }
  for (double& c : cover) c /= kSub * kSub;
  // Marching squares on the coverage at the pixel centres, iso-level 1/2, with
  // the crossings interpolated linearly: a sub-pixel outline whose length is
  // the boundary's, not a staircase's (a staircase is up to 4/pi longer on
  // diagonals, which would skew the arc-length resampling of outline_roundness).
  // Cell (x, y) has corners k = 0..3 at (x, y), (x+1, y), (x+1, y+1), (x, y+1),
  // counter-clockwise; edge k runs from corner k to corner k+1. Each crossing is
  // named by its grid edge (2 per pixel centre: to the right, and up).
  auto value = [&](int x, int y) { return cover[static_cast<std::size_t>(y) * nx + x]; };
  auto centre = [&](int x, int y) -> Vec2 { return origin + Vec2((x + 0.5) * pixel, (y + 0.5) * pixel); };
  const std::size_t edges = 2 * static_cast<std::size_t>(nx) * ny;
  std::vector<int> next(edges, -1);
  std::vector<Vec2> point(edges);
  constexpr int kCorner[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (int y = 0; y + 1 < ny; ++y) {
    for (int x = 0; x + 1 < nx; ++x) {
      double v[4];
      bool inside[4];
      int count = 0;
      for (int k = 0; k < 4; ++k) {
        v[k] = value(x + kCorner[k][0], y + kCorner[k][1]);
        inside[k] = v[k] > 0.5;
        count += inside[k];
      }
      if (count == 0 || count == 4) continue;
      int id[4] = {-1, -1, -1, -1};
      for (int k = 0; k < 4; ++k) {
        const int j = (k + 1) % 4;
        if (inside[k] == inside[j]) continue;
        const int ax = x + kCorner[k][0], ay = y + kCorner[k][1], bx = x + kCorner[j][0], by = y + kCorner[j][1];
        const int gx = std::min(ax, bx), gy = std::min(ay, by);
        id[k] = 2 * (gy * nx + gx) + (ay == by ? 0 : 1);
        const double t = (0.5 - v[k]) / (v[j] - v[k]);
        point[id[k]] = centre(ax, ay) + t * (centre(bx, by) - centre(ax, ay));
      }
      // Each in->out crossing (counter-clockwise round the cell) leads to an
      // out->in crossing, with the inside on the left: the next one round the
      // cell, or in a saddle whose centre is outside, the previous one.
      const bool centre_inside = 0.25 * (v[0] + v[1] + v[2] + v[3]) > 0.5;
      for (int k = 0; k < 4; ++k) {
        if (id[k] < 0 || !inside[k]) continue;
        for (int step = 1; step < 4; ++step) {
          const int j = count == 2 && inside[0] == inside[2] && !centre_inside ? (k - step + 4) % 4 : (k + step) % 4;
          if (id[j] >= 0 && !inside[j]) {
            next[id[k]] = id[j];
            break;
          }
        }
      }
    }
  }
  std::vector<Vec2> best;
  double best_area = 0;
  for (std::size_t start = 0; start < edges; ++start) {
    if (next[start] < 0) continue;
    std::vector<Vec2> loop;
    int e = static_cast<int>(start);
    while (e >= 0 && next[e] >= 0) {
      loop.push_back(point[e]);
      const int n = next[e];
      next[e] = -1;  // visited
      e = n;
    }
    const double a = signed_area(loop);
    if (a > best_area) {
      best_area = a;
      best = std::move(loop);
    }
  }
  return best;
}

double largest_inscribed_circle(std::span<const Vec2> outline, Vec2* centre) {
  if (outline.size() < 3) {
    if (centre) *centre = Vec2::Zero();
    return 0;
  }
  Vec2 lo = outline[0], hi = outline[0];
  for (const Vec2& p : outline) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  // Coarse grid, then a pattern search from the best grid point.
  constexpr int kGrid = 24;
  const Vec2 cell = (hi - lo) / kGrid;
  Vec2 best = 0.5 * (lo + hi);
  double best_d = signed_distance(outline, best);
  for (int i = 0; i < kGrid; ++i) {
    for (int j = 0; j < kGrid; ++j) {
      const Vec2 p = lo + Vec2((i + 0.5) * cell.x(), (j + 0.5) * cell.y());
      const double d = signed_distance(outline, p);
      if (d > best_d) {
        best_d = d;
        best = p;
      }
    }
  }
  double step = cell.maxCoeff();
  const double stop = 1e-7 * (hi - lo).norm();
  static const Vec2 kDirs[8] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1},
                                {0.7071067811865476, 0.7071067811865476},
                                {-0.7071067811865476, 0.7071067811865476},
                                {0.7071067811865476, -0.7071067811865476},
                                {-0.7071067811865476, -0.7071067811865476}};
  while (step > stop) {
    bool moved = false;
    for (const Vec2& d : kDirs) {
      const Vec2 p = best + step * d;
      const double v = signed_distance(outline, p);
      if (v > best_d) {
        best_d = v;
        best = p;
        moved = true;
      }
    }
    if (!moved) step *= 0.5;
  }
  if (centre) *centre = best;
  return std::max(0.0, best_d);
}

OutlineRoundness outline_roundness(std::span<const Vec2> outline_in) {
  OutlineRoundness out;
  std::vector<Vec2> outline(outline_in.begin(), outline_in.end());
  if (outline.size() < 3) return out;
  if (signed_area(outline) < 0) std::reverse(outline.begin(), outline.end());
  const double r_in = largest_inscribed_circle(outline);
  out.inscribed_radius = r_in;
  if (!(r_in > 0)) return out;

  double h = 0;
  const std::vector<Vec2> raw = resample(outline, kSamples, &h);
  const int n = kSamples;
  const int m = std::clamp(static_cast<int>(std::lround(kCornerScale * r_in / h)), 2, n / 8);
  const std::vector<Vec2> p = smooth(raw, m);

  // Signed local curvature radius: positive for convex (left) turns.
  std::vector<char> corner(static_cast<std::size_t>(n), 0);
  for (int i = 0; i < n; ++i) {
    const Vec2& a = p[(i - m + n) % n];
    const Vec2& b = p[i];
    const Vec2& c = p[(i + m) % n];
    const double turn = cross2(b - a, c - b);
    if (turn <= 0) continue;
    const double rho = (b - a).norm() * (c - b).norm() * (c - a).norm() / (2 * turn);
    corner[i] = rho < r_in;
  }
  // Runs of corner points, cyclic; start just after a non-corner point.
  int first = -1;
  for (int i = 0; i < n; ++i) {
    if (!corner[i]) {
      first = i;
      break;
    }
  }
  std::vector<std::vector<Vec2>> runs;
  if (first < 0) {
    runs.push_back(p);  // the whole outline curves like a circle
  } else {
    std::vector<Vec2> run;
    for (int k = 1; k <= n; ++k) {
      const int i = (first + k) % n;
      if (corner[i]) {
        run.push_back(p[i]);
      } else if (!run.empty()) {
        runs.push_back(std::move(run));
        run.clear();
      }
    }
  }
  double sum = 0;
  for (const auto& run : runs) {
    if (run.size() < 3) continue;
    sum += std::min(fit_circle_radius(run), r_in);
    ++out.corners;
  }
  if (out.corners > 0) {
    out.mean_corner_radius = sum / out.corners;
    out.roundness = std::min(1.0, out.mean_corner_radius / r_in);
  }
  return out;
}

PrincipalFrame principal_frame(const TriMesh& mesh) {
  const MassProperties mp = mass_properties(mesh);
  PrincipalFrame f;
  f.centroid = mp.centroid;
  Vec3 ext;
  for (int k = 0; k < 3; ++k) {
    const Vec3 axis = mp.principal_axes.col(k);
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const Vec3& v : mesh.vertices) {
      const double t = axis.dot(v - mp.centroid);
      lo = std::min(lo, t);
      hi = std::max(hi, t);
    }
    ext[k] = hi - lo;
  }
  // Order the axes by extent, largest first (stable: ties keep inertia order).
  std::array<int, 3> order{0, 1, 2};
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return ext[a] > ext[b]; });
  for (int k = 0; k < 3; ++k) {
    f.axes.col(k) = mp.principal_axes.col(order[k]);
    f.extents[k] = ext[order[k]];
  }
  f.axes.col(2) = f.axes.col(0).cross(f.axes.col(1));  // right-handed
  return f;
}

void move_to_principal_frame(TriMesh& mesh) {
  const PrincipalFrame f = principal_frame(mesh);
  for (Vec3& v : mesh.vertices) v = f.axes.transpose() * (v - f.centroid);
}

ShapeMetrics shape_metrics(const TriMesh& mesh) {
  ShapeMetrics s;
  const MassProperties mp = mass_properties(mesh);
  if (!(mp.volume > 0)) {
    input_error("shape metrics: the mesh has volume {} (not a closed outward solid); load it "
                "through load_mesh() first",
                mp.volume);
  }
  s.volume = mp.volume;
  for (const Face& f : mesh.faces) {
    const Vec3& a = mesh.vertices[f[0]];
    s.surface_area += 0.5 * (mesh.vertices[f[1]] - a).cross(mesh.vertices[f[2]] - a).norm();
  }
  s.equivalent_diameter = std::cbrt(6.0 * s.volume / std::numbers::pi);
  s.sphericity = std::cbrt(std::numbers::pi) * std::pow(6.0 * s.volume, 2.0 / 3.0) / s.surface_area;

  const PrincipalFrame f = principal_frame(mesh);
  s.long_axis = f.extents[0];
  s.intermediate_axis = f.extents[1];
  s.short_axis = f.extents[2];
  s.elongation = s.intermediate_axis / s.long_axis;
  s.flatness = s.short_axis / s.intermediate_axis;

  const ConvexHull hull = convex_hull(mesh.vertices);
  s.convexity = std::min(1.0, s.volume / mass_properties(hull.mesh()).volume);

  // Outlines on the three principal planes: convex hull of the projected hull
  // vertices for convex grains, the rasterised silhouette otherwise.
  const bool convex = s.convexity >= kConvexLimit;
  const std::vector<Vec3>& src = convex ? hull.vertices : mesh.vertices;
  constexpr int kPlanes[3][2] = {{0, 1}, {0, 2}, {1, 2}};
  std::vector<Vec2> proj(src.size());
  double sum = 0;
  for (int k = 0; k < 3; ++k) {
    const Vec3 u = f.axes.col(kPlanes[k][0]), v = f.axes.col(kPlanes[k][1]);
    for (std::size_t i = 0; i < src.size(); ++i) {
      const Vec3 d = src[i] - f.centroid;
      proj[i] = Vec2(u.dot(d), v.dot(d));
    }
    const std::vector<Vec2> outline =
        convex ? convex_outline(proj) : silhouette_outline(proj, mesh.faces);
    s.projection_roundness[k] = outline_roundness(outline).roundness;
    sum += s.projection_roundness[k];
  }
  s.roundness = sum / 3;
  return s;
}

}  // namespace grainlab
