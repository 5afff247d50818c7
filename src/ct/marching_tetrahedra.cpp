#include "ct/marching_tetrahedra.h"

#include <algorithm>
#include <array>
#include <numeric>
#include <unordered_map>

namespace grainlab::ct {

namespace {

// The six Kuhn tetrahedra of a cube, corners as bit masks (bit 0 = +x, 1 = +y, 2 = +z).
constexpr std::array<std::array<int, 4>, 6> kTets = {{
    {0, 1, 3, 7}, {0, 1, 5, 7}, {0, 2, 3, 7}, {0, 2, 6, 7}, {0, 4, 5, 7}, {0, 4, 6, 7},
}};

constexpr float kEdgeMargin = 1e-3f;

double signed_volume(const TriMesh& m) {
  double v = 0;
  for (const Face& f : m.faces) v += m.vertices[f[0]].dot(m.vertices[f[1]].cross(m.vertices[f[2]])) / 6;
  return v;
}

}  // namespace

TriMesh iso_surface(const std::vector<float>& field, const Size3& size, float iso) {
  const std::int64_t nx = size[0], ny = size[1], nz = size[2];
  TriMesh mesh;
  // Vertex ids by edge: (lower grid point) * 8 + (offset bits to the upper one).
  std::unordered_map<std::uint64_t, Index> edge_vertex;
  auto point = [&](std::int64_t g) {
    return Vec3(static_cast<double>(g % nx), static_cast<double>((g / nx) % ny), static_cast<double>(g / (nx * ny)));
  };
  auto vertex_on = [&](std::int64_t ga, int ca, std::int64_t gb, int cb) {
    if (ca > cb) {  // order the edge from the lower corner bit mask (a subset) to the upper
      std::swap(ga, gb);
      std::swap(ca, cb);
    }
    const std::uint64_t key = static_cast<std::uint64_t>(ga) * 8 + static_cast<std::uint64_t>(cb ^ ca);
    const auto it = edge_vertex.find(key);
    if (it != edge_vertex.end()) return it->second;
    const float fa = field[ga], fb = field[gb];
    const float t = std::clamp((iso - fa) / (fb - fa), kEdgeMargin, 1 - kEdgeMargin);
    const Index id = static_cast<Index>(mesh.vertices.size());
    mesh.vertices.push_back(point(ga) + t * (point(gb) - point(ga)));
    edge_vertex.emplace(key, id);
    return id;
  };
  auto emit = [&](Index a, Index b, Index c, const Vec3& towards_outside) {
    const Vec3& p = mesh.vertices[a];
    const Vec3 n = (mesh.vertices[b] - p).cross(mesh.vertices[c] - p);
    if (n.dot(towards_outside) >= 0) {
      mesh.faces.push_back({a, b, c});
    } else {
      mesh.faces.push_back({a, c, b});
    }
  };

  for (std::int64_t k = 0; k + 1 < nz; ++k) {
    for (std::int64_t j = 0; j + 1 < ny; ++j) {
      for (std::int64_t i = 0; i + 1 < nx; ++i) {
        std::array<std::int64_t, 8> g;
        std::array<bool, 8> in;
        int inside = 0;
        for (int c = 0; c < 8; ++c) {
          g[c] = (i + (c & 1)) + nx * ((j + ((c >> 1) & 1)) + ny * (k + ((c >> 2) & 1)));
          in[c] = field[g[c]] > iso;
          inside += in[c];
        }
        if (inside == 0 || inside == 8) continue;
        for (const auto& tet : kTets) {
          std::array<int, 4> ins{}, outs{};
          int ni = 0, no = 0;
          for (int c : tet) (in[c] ? ins[ni++] : outs[no++]) = c;
          if (ni == 0 || no == 0) continue;
          Vec3 mean_in = Vec3::Zero(), mean_out = Vec3::Zero();
          for (int q = 0; q < ni; ++q) mean_in += point(g[ins[q]]) / ni;
          for (int q = 0; q < no; ++q) mean_out += point(g[outs[q]]) / no;
          const Vec3 out_dir = mean_out - mean_in;
          if (ni == 1 || no == 1) {
            // One corner alone: a triangle on its three edges.
            const int lone = ni == 1 ? ins[0] : outs[0];
            const auto& others = ni == 1 ? outs : ins;
            const Index a = vertex_on(g[lone], lone, g[others[0]], others[0]);
            const Index b = vertex_on(g[lone], lone, g[others[1]], others[1]);
            const Index c = vertex_on(g[lone], lone, g[others[2]], others[2]);
            emit(a, b, c, out_dir);
          } else {
            // Two and two: the quadrilateral (in0-out0, in0-out1, in1-out1, in1-out0), split in two.
            const Index a = vertex_on(g[ins[0]], ins[0], g[outs[0]], outs[0]);
            const Index b = vertex_on(g[ins[0]], ins[0], g[outs[1]], outs[1]);
            const Index c = vertex_on(g[ins[1]], ins[1], g[outs[1]], outs[1]);
            const Index d = vertex_on(g[ins[1]], ins[1], g[outs[0]], outs[0]);
            emit(a, b, c, out_dir);
            emit(a, c, d, out_dir);
          }
        }
      }
    }
  }
  return mesh;
}

std::vector<TriMesh> mesh_components(const TriMesh& mesh) {
  std::vector<Index> parent(mesh.vertices.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](Index v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  for (const Face& f : mesh.faces) {
    parent[find(f[1])] = find(f[0]);
    parent[find(f[2])] = find(f[0]);
  }
  std::unordered_map<Index, std::size_t> piece_of_root;
  std::vector<TriMesh> pieces;
  std::vector<Index> new_id(mesh.vertices.size(), -1);
  for (const Face& f : mesh.faces) {
    const Index root = find(f[0]);
    auto [it, fresh] = piece_of_root.try_emplace(root, pieces.size());
    if (fresh) pieces.emplace_back();
    TriMesh& p = pieces[it->second];
    Face nf;
    for (int c = 0; c < 3; ++c) {
      if (new_id[f[c]] < 0) {
        new_id[f[c]] = static_cast<Index>(p.vertices.size());
        p.vertices.push_back(mesh.vertices[f[c]]);
      }
      nf[c] = new_id[f[c]];
    }
    p.faces.push_back(nf);
  }
  std::vector<double> volume(pieces.size());
  for (std::size_t i = 0; i < pieces.size(); ++i) volume[i] = signed_volume(pieces[i]);
  std::vector<std::size_t> order(pieces.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return volume[a] > volume[b]; });
  std::vector<TriMesh> sorted;
  for (std::size_t i : order) sorted.push_back(std::move(pieces[i]));
  return sorted;
}

}  // namespace grainlab::ct
