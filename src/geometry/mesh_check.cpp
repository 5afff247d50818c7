// Finding and repairing mesh defects.
//
// Edges. Every face (a, b, c) contributes the directed edges a->b, b->c,
// c->a. Grouped by their unordered vertex pair, a closed 2-manifold has
// exactly two faces per edge (one: a hole; more: non-manifold), and a
// consistently wound one traverses each edge once in each direction.
//
// Orientation. On a closed manifold, breadth-first search over faces
// (neighbours across shared edges) fixes each face's flip relative to the
// first face of its component: a neighbour that runs the shared edge in the
// same direction must take the opposite flip. A face reached twice with
// contradicting flips means the surface is non-orientable. Each component is
// then flipped as a whole if its signed volume sum a.(b x c)/6 is negative,
// which is the divergence-theorem volume and positive exactly when the
// normals point out.
//
// Merging. Vertices closer than tol = kMergeTolerance * (bounding-box
// diagonal) are merged into the first of them. Points are hashed into cubic
// cells of side tol, so any point within tol of another lies in one of the
// 27 cells around it; only kept (representative) vertices enter the grid,
// so representatives are pairwise farther apart than tol.
#include "geometry/mesh_check.h"

#include "core/error.h"
#include "geometry/mesh_io.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <numeric>
#include <unordered_map>

namespace grainlab {
namespace {

// Zero-area threshold for |(b-a) x (c-a)|, relative to the squared diagonal.
constexpr double kAreaTolerance = 1e-14;
// Zero-volume threshold relative to the cubed diagonal.
constexpr double kVolumeTolerance = 1e-12;

bool finite(const Vec3& v) { return v.allFinite(); }

// Bounding-box diagonal of the finite vertices (0 if none).
double bbox_diagonal(const std::vector<Vec3>& vertices) {
  Vec3 lo = Vec3::Constant(INFINITY), hi = Vec3::Constant(-INFINITY);
  bool any = false;
  for (const Vec3& v : vertices) {
    if (!finite(v)) continue;
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
    any = true;
  }
  return any ? (hi - lo).norm() : 0.0;
}

bool has_bad_index(const Face& f, std::size_t n) {
  for (Index i : f) {
    if (i < 0 || static_cast<std::size_t>(i) >= n) return true;
  }
  return false;
}

bool repeated_index(const Face& f) { return f[0] == f[1] || f[1] == f[2] || f[2] == f[0]; }

// Maps each vertex to the first vertex within `tol` of it (itself if none).
// Non-finite vertices map to themselves.
std::vector<Index> merge_map(const std::vector<Vec3>& vertices, double tol) {
  const auto n = static_cast<Index>(vertices.size());
  std::vector<Index> map(n);
  std::iota(map.begin(), map.end(), 0);
  struct Key {
    std::int64_t x, y, z;
    bool operator==(const Key&) const = default;
  };
  struct KeyHash {
    std::size_t operator()(const Key& k) const {
      return static_cast<std::size_t>(k.x * 73856093LL ^ k.y * 19349663LL ^ k.z * 83492791LL);
    }
  };
  std::unordered_map<Key, std::vector<Index>, KeyHash> grid;
  grid.reserve(vertices.size());
  const double cell = tol > 0 ? tol : 1.0;
  for (Index i = 0; i < n; ++i) {
    const Vec3& p = vertices[i];
    if (!finite(p)) continue;
    const Key k{static_cast<std::int64_t>(std::floor(p.x() / cell)),
                static_cast<std::int64_t>(std::floor(p.y() / cell)),
                static_cast<std::int64_t>(std::floor(p.z() / cell))};
    Index found = -1;
    for (int dx = -1; dx <= 1 && found < 0; ++dx) {
      for (int dy = -1; dy <= 1 && found < 0; ++dy) {
        for (int dz = -1; dz <= 1 && found < 0; ++dz) {
          auto it = grid.find(Key{k.x + dx, k.y + dy, k.z + dz});
          if (it == grid.end()) continue;
          for (Index j : it->second) {
            if ((vertices[j] - p).norm() <= tol) {
              found = j;
              break;
            }
          }
        }
      }
    }
    if (found >= 0) {
      map[i] = found;
    } else {
      grid[k].push_back(i);
    }
  }
  return map;
}

// One directed edge of a face, keyed by its unordered vertex pair.
struct HalfEdge {
  Index lo, hi;   // lo < hi
  Index face;
  Index slot;     // edge k runs from f[k] to f[(k+1)%3]
  bool forward;   // runs lo -> hi
};

// Half-edges of the faces that can take part in a surface, sorted by edge.
std::vector<HalfEdge> half_edges(const std::vector<Face>& faces, std::size_t nvert) {
  std::vector<HalfEdge> he;
  he.reserve(faces.size() * 3);
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const Face& t = faces[f];
    if (has_bad_index(t, nvert) || repeated_index(t)) continue;
    for (Index k = 0; k < 3; ++k) {
      const Index u = t[k], v = t[(k + 1) % 3];
      he.push_back({std::min(u, v), std::max(u, v), static_cast<Index>(f), k, u < v});
    }
  }
  std::sort(he.begin(), he.end(), [](const HalfEdge& a, const HalfEdge& b) {
    return a.lo != b.lo ? a.lo < b.lo : (a.hi != b.hi ? a.hi < b.hi : a.face < b.face);
  });
  return he;
}

// Union-find root with path halving.
Index find_root(std::vector<Index>& parent, Index i) {
  while (parent[i] != i) {
    parent[i] = parent[parent[i]];
    i = parent[i];
  }
  return i;
}

// Signed volume of the faces listed (all indices valid), about `origin`.
double signed_volume(const TriMesh& m, const std::vector<Index>& faces, const Vec3& origin) {
  double six_v = 0;
  for (Index f : faces) {
    const Face& t = m.faces[f];
    const Vec3 a = m.vertices[t[0]] - origin, b = m.vertices[t[1]] - origin,
               c = m.vertices[t[2]] - origin;
    six_v += a.dot(b.cross(c));
  }
  return six_v / 6.0;
}

Vec3 vertex_mean(const std::vector<Vec3>& vertices) {
  Vec3 s = Vec3::Zero();
  for (const Vec3& v : vertices) s += v;
  return vertices.empty() ? s : Vec3(s / static_cast<double>(vertices.size()));
}

// Plural helper for messages: "1 edge", "3 edges".
std::string count(Index n, const char* one, const char* many) {
  return fmt::format("{} {}", n, n == 1 ? one : many);
}

}  // namespace

bool MeshCheck::ok() const {
  return faces > 0 && bad_indices == 0 && non_finite_vertices == 0 && repeated_index_faces == 0 &&
         open_edges == 0 && non_manifold_edges == 0 && inconsistent_edges == 0 &&
         duplicate_vertices == 0 && unused_vertices == 0 && !inside_out && signed_volume > 0;
}

std::string MeshCheck::describe() const {
  std::vector<std::string> parts;
  if (faces == 0) parts.push_back("no faces (empty mesh)");
  if (bad_indices) parts.push_back(count(bad_indices, "face with a vertex index out of range", "faces with vertex indices out of range"));
  if (non_finite_vertices) parts.push_back(count(non_finite_vertices, "non-finite vertex", "non-finite vertices"));
  if (degenerate_faces) parts.push_back(count(degenerate_faces, "degenerate (zero-area) face", "degenerate (zero-area) faces"));
  if (repeated_index_faces) parts.push_back(count(repeated_index_faces, "face with a repeated vertex", "faces with a repeated vertex"));
  if (open_edges) parts.push_back(count(open_edges, "open edge (boundary)", "open edges (boundary)"));
  if (non_manifold_edges) parts.push_back(count(non_manifold_edges, "non-manifold edge (more than 2 faces)", "non-manifold edges (more than 2 faces)"));
  if (inconsistent_edges) parts.push_back(count(inconsistent_edges, "edge with inconsistent orientation", "edges with inconsistent orientation"));
  if (inside_out) parts.push_back(fmt::format("inside out (signed volume {:.6g})", signed_volume));
  if (duplicate_vertices) parts.push_back(count(duplicate_vertices, "duplicate vertex", "duplicate vertices"));
  if (unused_vertices) parts.push_back(count(unused_vertices, "unused vertex", "unused vertices"));
  if (faces > 0 && !inside_out && open_edges == 0 && non_manifold_edges == 0 && inconsistent_edges == 0 &&
      non_finite_vertices == 0 && bad_indices == 0 && !(signed_volume > 0)) {
    parts.push_back("zero volume");
  }
  if (parts.empty()) return "closed, manifold, outward";
  std::string s = parts[0];
  for (std::size_t i = 1; i < parts.size(); ++i) s += ", " + parts[i];
  return s;
}

MeshCheck check_mesh(const TriMesh& mesh) {
  MeshCheck c;
  const std::size_t nv = mesh.vertices.size();
  c.vertices = static_cast<Index>(nv);
  c.faces = static_cast<Index>(mesh.faces.size());
  for (const Vec3& v : mesh.vertices) c.non_finite_vertices += finite(v) ? 0 : 1;

  const double diag = bbox_diagonal(mesh.vertices);
  std::vector<char> used(nv, 0);
  for (const Face& f : mesh.faces) {
    if (has_bad_index(f, nv)) {
      ++c.bad_indices;
      continue;
    }
    for (Index i : f) used[i] = 1;
    if (repeated_index(f)) {
      ++c.repeated_index_faces;
      ++c.degenerate_faces;
      continue;
    }
    const Vec3& a = mesh.vertices[f[0]];
    const double area2 = (mesh.vertices[f[1]] - a).cross(mesh.vertices[f[2]] - a).norm();
    if (!(area2 > kAreaTolerance * diag * diag)) ++c.degenerate_faces;
  }
  for (std::size_t i = 0; i < nv; ++i) c.unused_vertices += used[i] ? 0 : 1;

  const std::vector<Index> map = merge_map(mesh.vertices, kMergeTolerance * diag);
  for (std::size_t i = 0; i < nv; ++i) c.duplicate_vertices += map[i] != static_cast<Index>(i) ? 1 : 0;

  // Edges and components.
  const std::vector<HalfEdge> he = half_edges(mesh.faces, nv);
  std::vector<Index> parent(mesh.faces.size());
  std::iota(parent.begin(), parent.end(), 0);
  for (std::size_t i = 0; i < he.size();) {
    std::size_t j = i;
    while (j < he.size() && he[j].lo == he[i].lo && he[j].hi == he[i].hi) ++j;
    const std::size_t k = j - i;
    if (k == 1) ++c.open_edges;
    if (k > 2) ++c.non_manifold_edges;
    if (k == 2 && he[i].forward == he[i + 1].forward) ++c.inconsistent_edges;
    i = j;
  }
  for (std::size_t e = 1; e < he.size(); ++e) {
    if (he[e].lo == he[e - 1].lo && he[e].hi == he[e - 1].hi) {
      parent[find_root(parent, he[e].face)] = find_root(parent, he[e - 1].face);
    }
  }
  std::vector<Index> surface_faces;
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    if (has_bad_index(mesh.faces[f], nv) || repeated_index(mesh.faces[f])) continue;
    surface_faces.push_back(static_cast<Index>(f));
    if (find_root(parent, static_cast<Index>(f)) == static_cast<Index>(f)) ++c.components;
  }

  if (c.bad_indices == 0 && c.non_finite_vertices == 0) {
    c.signed_volume = signed_volume(mesh, surface_faces, vertex_mean(mesh.vertices));
    c.inside_out = c.open_edges == 0 && c.non_manifold_edges == 0 && c.inconsistent_edges == 0 &&
                   c.signed_volume < 0;
  }
  return c;
}

TriMesh repair_mesh(const TriMesh& mesh, const std::string& name, std::vector<std::string>* notes) {
  const std::size_t nv0 = mesh.vertices.size();
  if (mesh.faces.empty() || nv0 == 0) {
    input_error("mesh '{}': the mesh is empty (no faces); export the grain's closed surface", name);
  }
  Index bad = 0;
  for (const Face& f : mesh.faces) bad += has_bad_index(f, nv0) ? 1 : 0;
  if (bad) {
    input_error("mesh '{}': {} refer to vertices that do not exist; the file is corrupt, re-export the mesh",
                name, count(bad, "face", "faces"));
  }
  Index nonfinite = 0;
  for (const Vec3& v : mesh.vertices) nonfinite += finite(v) ? 0 : 1;
  if (nonfinite) {
    input_error("mesh '{}': {} non-finite (NaN or infinite) coordinates; re-export the mesh",
                name, count(nonfinite, "vertex has", "vertices have"));
  }

  // Merge duplicates, drop faces that collapse to a repeated vertex.
  const double diag = bbox_diagonal(mesh.vertices);
  const std::vector<Index> map = merge_map(mesh.vertices, kMergeTolerance * diag);
  std::vector<Face> faces;
  faces.reserve(mesh.faces.size());
  for (const Face& f : mesh.faces) {
    const Face g{map[f[0]], map[f[1]], map[f[2]]};
    if (!repeated_index(g)) faces.push_back(g);
  }
  if (faces.empty()) {
    input_error("mesh '{}': every face is degenerate (repeats a vertex); the mesh has no surface, re-export it", name);
  }

  // Keep used vertices only, in their original order.
  std::vector<Index> renumber(nv0, -1);
  TriMesh out;
  for (Face& f : faces) {
    for (Index& i : f) {
      if (renumber[i] < 0) renumber[i] = 0;  // mark used
    }
  }
  for (std::size_t i = 0; i < nv0; ++i) {
    if (renumber[i] >= 0) {
      renumber[i] = static_cast<Index>(out.vertices.size());
      out.vertices.push_back(mesh.vertices[i]);
    }
  }
  for (Face& f : faces) {
    for (Index& i : f) i = renumber[i];
  }
  out.faces = std::move(faces);

  // Edge topology: refuse holes and non-manifold edges; record neighbours.
  const std::size_t nf = out.faces.size();
  const std::vector<HalfEdge> he = half_edges(out.faces, out.vertices.size());
  Index open = 0, nonmanifold = 0;
  // neighbour[3 f + k]: face across edge k of f, and whether it runs that edge the same way.
  std::vector<Index> neighbour(3 * nf, -1);
  std::vector<char> same_dir(3 * nf, 0);
  for (std::size_t i = 0; i < he.size();) {
    std::size_t j = i;
    while (j < he.size() && he[j].lo == he[i].lo && he[j].hi == he[i].hi) ++j;
    if (j - i == 1) ++open;
    if (j - i > 2) ++nonmanifold;
    if (j - i == 2) {
      const HalfEdge &a = he[i], &b = he[i + 1];
      const char same = a.forward == b.forward ? 1 : 0;
      neighbour[3 * a.face + a.slot] = b.face;
      neighbour[3 * b.face + b.slot] = a.face;
      same_dir[3 * a.face + a.slot] = same;
      same_dir[3 * b.face + b.slot] = same;
    }
    i = j;
  }
  if (open) {
    input_error("mesh '{}': the surface is open: {} (holes); close the holes (e.g. MeshLab "
                "'Close Holes') and re-export a watertight mesh",
                name, count(open, "edge belongs to only one face", "edges belong to only one face"));
  }
  if (nonmanifold) {
    input_error("mesh '{}': {} (non-manifold); remove duplicate, internal or touching faces "
                "(e.g. MeshLab 'Repair non Manifold Edges') and re-export",
                name, count(nonmanifold, "edge is shared by more than two faces", "edges are shared by more than two faces"));
  }

  // Consistent winding by breadth-first search, then outward per component.
  std::vector<signed char> flip(nf, -1);  // -1: not reached
  std::deque<Index> queue;
  const Vec3 origin = vertex_mean(out.vertices);
  for (std::size_t s = 0; s < nf; ++s) {
    if (flip[s] >= 0) continue;
    std::vector<Index> component{static_cast<Index>(s)};
    flip[s] = 0;
    queue.push_back(static_cast<Index>(s));
    while (!queue.empty()) {
      const Index f = queue.front();
      queue.pop_front();
      for (int k = 0; k < 3; ++k) {
        const Index g = neighbour[3 * f + k];
        const signed char want = same_dir[3 * f + k] ? static_cast<signed char>(1 - flip[f]) : flip[f];
        if (flip[g] < 0) {
          flip[g] = want;
          component.push_back(g);
          queue.push_back(g);
        } else if (flip[g] != want) {
          input_error("mesh '{}': the surface is non-orientable (no consistent inside and outside); "
                      "it cannot be a solid grain, rebuild the mesh",
                      name);
        }
      }
    }
    for (Index f : component) {
      if (flip[f]) std::swap(out.faces[f][1], out.faces[f][2]);
    }
    const double v = signed_volume(out, component, origin);
    if (!(std::abs(v) > kVolumeTolerance * diag * diag * diag)) {
      input_error("mesh '{}': a closed part of {} encloses zero volume (flat or folded onto "
                  "itself); remove it and re-export",
                  name, count(static_cast<Index>(component.size()), "face", "faces"));
    }
    if (v < 0) {
      for (Index f : component) std::swap(out.faces[f][1], out.faces[f][2]);
      if (notes)
        notes->push_back(fmt::format("mesh '{}': {} wound inward (normals pointing into the grain, signed volume "
                                     "{:.4g} in the file's units cubed); turned outward. Export it with outward normals "
                                     "to be rid of this note",
                                     name, count(static_cast<Index>(component.size()), "face is", "faces are"), v));
    }
  }
  return out;
}

TriMesh load_mesh(const std::filesystem::path& path, std::vector<std::string>* notes) {
  const std::string name = path.string();
  TriMesh m = repair_mesh(read_mesh(path), name, notes);
  const MeshCheck c = check_mesh(m);
  if (!c.ok()) {
    input_error("mesh '{}': still defective after repair: {}; fix it in a mesh editor and re-export",
                name, c.describe());
  }
  return m;
}

}  // namespace grainlab
