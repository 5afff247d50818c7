// Convex hull through qhull (reentrant C API), plus its vertex adjacency.
//
// qhull is run with "Qt" (triangulated output): merged coplanar facets come
// back as triangles that share the merged facet's outward normal (some may
// have zero area). Each triangle's winding is set from that normal: with
// n_tri = (b - a) x (c - a), the order is kept if n_tri . n_facet > 0 and two
// vertices are swapped otherwise; a zero-area triangle, whose n_tri vanishes,
// falls back to the direction from the interior point (the vertex mean) to
// its centroid. The edges of these triangles contain every edge of the true
// polytope (plus diagonals inside flat facets), so a vertex with no
// neighbour of larger support value d . x is a global maximiser of d . x over
// the hull: greedy ascent over this graph finds the support point.
#include "geometry/convex_hull.h"

#include "geometry/mass_properties.h"

#include "core/error.h"

#include <libqhull_r/qhull_ra.h>  // declares its functions extern "C" itself

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace grainlab {
namespace {

// Frees qhull's memory however the run ended.
struct QhullRun {
  qhT state;
  qhT* qh = &state;
  QhullRun() { qh_zero(qh, nullptr); }
  ~QhullRun() {
    qh_freeqhull(qh, !qh_ALL);
    int curlong = 0, totlong = 0;
    qh_memfreeshort(qh, &curlong, &totlong);
  }
  QhullRun(const QhullRun&) = delete;
  QhullRun& operator=(const QhullRun&) = delete;
};

}  // namespace

ConvexHull convex_hull(std::span<const Vec3> points) {
  if (points.size() < 4) {
    input_error("convex hull: needs at least 4 points, got {}", points.size());
  }
  std::vector<coordT> coords;
  coords.reserve(points.size() * 3);
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!points[i].allFinite()) {
      input_error("convex hull: point {} is not finite ({}, {}, {})", i, points[i].x(), points[i].y(),
                  points[i].z());
    }
    coords.insert(coords.end(), {points[i].x(), points[i].y(), points[i].z()});
  }
  // qhull reports coincident input as an internal error; say what it is.
  if (std::all_of(points.begin(), points.end(), [&](const Vec3& p) { return p == points[0]; })) {
    input_error("convex hull: all {} points coincide, so they bound no volume", points.size());
  }

  // qhull's messages go to a memory stream so that they can be quoted, not printed.
  char* err_text = nullptr;
  std::size_t err_len = 0;
  FILE* err = open_memstream(&err_text, &err_len);
  ConvexHull hull;
  int code = 0;
  {
    QhullRun run;
    qhT* qh = run.qh;
    char options[] = "qhull Qt";
    code = qh_new_qhull(qh, 3, static_cast<int>(points.size()), coords.data(), False, options,
                        nullptr, err ? err : stderr);
    if (code == qh_ERRnone) {
      // Renumber hull vertices by input order.
      std::vector<Index> new_id(points.size(), -1);
      vertexT* vertex;
      FORALLvertices { new_id[qh_pointid(qh, vertex->point)] = 0; }
      for (std::size_t i = 0; i < points.size(); ++i) {
        if (new_id[i] >= 0) {
          new_id[i] = static_cast<Index>(hull.vertices.size());
          hull.vertices.push_back(points[i]);
          hull.input_index.push_back(static_cast<Index>(i));
        }
      }
      Vec3 inside = Vec3::Zero();
      for (const Vec3& v : hull.vertices) inside += v;
      inside /= static_cast<double>(hull.vertices.size());

      facetT* facet;
      FORALLfacets {
        Face f{};
        int k = 0;
        vertexT** vertexp;
        FOREACHvertex_(facet->vertices) {
          if (k < 3) f[k] = new_id[qh_pointid(qh, vertex->point)];
          ++k;
        }
        if (k != 3) {
          code = qh_ERRqhull;  // "Qt" promises triangles
          break;
        }
        const Vec3 &a = hull.vertices[f[0]], &b = hull.vertices[f[1]], &c = hull.vertices[f[2]];
        const Vec3 n = (b - a).cross(c - a);
        const Vec3 facet_normal(facet->normal[0], facet->normal[1], facet->normal[2]);
        double s = n.dot(facet_normal);
        if (n.squaredNorm() == 0 || s == 0) s = facet_normal.dot((a + b + c) / 3.0 - inside);
        if (s < 0) std::swap(f[1], f[2]);
        hull.faces.push_back(f);
      }
    }
  }
  if (err) std::fclose(err);
  std::string message = err_text ? std::string(err_text, err_len) : std::string();
  std::free(err_text);
  if (code != qh_ERRnone) {
    const std::string first_line = message.substr(0, message.find('\n'));
    if (code == qh_ERRsingular || code == qh_ERRprec || code == qh_ERRtopology || code == qh_ERRwide) {
      input_error("convex hull: the {} points are (nearly) coplanar or coincident, so they bound no "
                  "volume (qhull error {}: {})",
                  points.size(), code, first_line);
    }
    input_error("convex hull: qhull failed with error {} ({})", code, first_line);
  }

  // Vertex adjacency (CSR) from the triangle edges, sorted, without duplicates.
  const std::size_t nv = hull.vertices.size();
  std::vector<std::vector<Index>> nbr(nv);
  for (const Face& f : hull.faces) {
    for (int k = 0; k < 3; ++k) {
      nbr[f[k]].push_back(f[(k + 1) % 3]);
      nbr[f[(k + 1) % 3]].push_back(f[k]);
    }
  }
  hull.adjacency_offsets.assign(nv + 1, 0);
  for (std::size_t v = 0; v < nv; ++v) {
    std::sort(nbr[v].begin(), nbr[v].end());
    nbr[v].erase(std::unique(nbr[v].begin(), nbr[v].end()), nbr[v].end());
    hull.adjacency_offsets[v + 1] = hull.adjacency_offsets[v] + static_cast<Index>(nbr[v].size());
    hull.adjacency.insert(hull.adjacency.end(), nbr[v].begin(), nbr[v].end());
  }
  return hull;
}

bool is_convex(const TriMesh& mesh, double tol) {
  if (mesh.vertices.empty() || mesh.faces.empty()) return false;
  Vec3 lo = mesh.vertices[0], hi = mesh.vertices[0];
  for (const Vec3& v : mesh.vertices) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  const double diag = (hi - lo).norm();
  const double limit = tol * diag;
  for (const Face& f : mesh.faces) {
    const Vec3& a = mesh.vertices[f[0]];
    const Vec3 n = (mesh.vertices[f[1]] - a).cross(mesh.vertices[f[2]] - a);
    const double len = n.norm();
    if (!(len > 1e-14 * diag * diag)) continue;  // zero-area face: no plane
    const Vec3 u = n / len;
    for (const Vec3& v : mesh.vertices) {
      if (u.dot(v - a) > limit) return false;
    }
  }
  return true;
}

double convexity(const TriMesh& mesh) {
  return mass_properties(mesh).volume / mass_properties(convex_hull(mesh.vertices).mesh()).volume;
}

}  // namespace grainlab
