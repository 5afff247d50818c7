// Convex hull: containment, extremality, topology, adjacency and hill climbing.
#include "geometry/convex_hull.h"

#include "geometry/mass_properties.h"
#include "geometry/primitives.h"
#include "test_helpers.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace grainlab {
namespace {

std::vector<Vec3> random_points(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec3> p(n);
  for (Vec3& v : p) v = Vec3(u(rng), u(rng), u(rng));
  return p;
}

Vec3 face_normal(const ConvexHull& h, const Face& f) {
  return (h.vertices[f[1]] - h.vertices[f[0]]).cross(h.vertices[f[2]] - h.vertices[f[0]]);
}

// Neighbours of v in the CSR adjacency.
std::span<const Index> neighbours(const ConvexHull& h, Index v) {
  return {h.adjacency.data() + h.adjacency_offsets[v],
          static_cast<std::size_t>(h.adjacency_offsets[v + 1] - h.adjacency_offsets[v])};
}

TEST(ConvexHull, RandomPointsContainedAndExtreme) {
  const std::vector<Vec3> pts = random_points(500, 42);
  const ConvexHull h = convex_hull(pts);
  ASSERT_GE(h.vertices.size(), 4u);
  EXPECT_LT(h.vertices.size(), pts.size());
  // Every hull vertex is an input point: the one its input_index names, in input order.
  ASSERT_EQ(h.input_index.size(), h.vertices.size());
  for (std::size_t k = 0; k < h.vertices.size(); ++k) {
    EXPECT_EQ(h.vertices[k], pts[h.input_index[k]]) << "hull vertex " << k;
    if (k > 0) {
      EXPECT_LT(h.input_index[k - 1], h.input_index[k]);
    }
  }
  // Every point is on the inner side of every face.
  for (const Face& f : h.faces) {
    const Vec3 n = face_normal(h, f);
    if (n.norm() == 0) continue;
    const Vec3 u = n.normalized();
    for (const Vec3& p : pts) EXPECT_LE(u.dot(p - h.vertices[f[0]]), 1e-12);
  }
  // Every hull vertex is the unique maximiser along the sum of its incident face normals.
  std::vector<Vec3> dir(h.vertices.size(), Vec3::Zero());
  for (const Face& f : h.faces) {
    const Vec3 n = face_normal(h, f);
    if (n.norm() == 0) continue;
    for (Index i : f) dir[i] += n.normalized();
  }
  for (std::size_t v = 0; v < h.vertices.size(); ++v) {
    const double top = dir[v].dot(h.vertices[v]);
    for (const Vec3& p : pts) {
      if (p != h.vertices[v]) {
        EXPECT_LT(dir[v].dot(p), top - 1e-12) << "hull vertex " << v;
      }
    }
  }
  // Outward: positive volume.
  EXPECT_GT(mass_properties(h.mesh()).volume, 0);
}

TEST(ConvexHull, EulerCharacteristicAndSymmetricAdjacency) {
  const ConvexHull h = convex_hull(random_points(300, 7));
  const auto V = static_cast<long>(h.vertices.size());
  const auto F = static_cast<long>(h.faces.size());
  ASSERT_EQ(h.adjacency_offsets.size(), h.vertices.size() + 1);
  const auto E2 = static_cast<long>(h.adjacency.size());
  ASSERT_EQ(E2 % 2, 0);
  EXPECT_EQ(V - E2 / 2 + F, 2);
  EXPECT_EQ(3 * F, E2);  // every edge in two triangles
  for (Index v = 0; v < V; ++v) {
    const auto nb = neighbours(h, v);
    EXPECT_TRUE(std::is_sorted(nb.begin(), nb.end()));
    EXPECT_EQ(std::adjacent_find(nb.begin(), nb.end()), nb.end()) << "duplicate neighbour of " << v;
    EXPECT_GE(nb.size(), 3u);
    for (Index w : nb) {
      EXPECT_NE(w, v);
      const auto back = neighbours(h, w);
      EXPECT_TRUE(std::binary_search(back.begin(), back.end(), v)) << v << " - " << w;
    }
  }
}

TEST(ConvexHull, IcosphereKeepsAllVertices) {
  const TriMesh s = icosphere(1.5, 3);
  const ConvexHull h = convex_hull(s.vertices);
  EXPECT_EQ(h.vertices.size(), s.vertices.size());
  EXPECT_EQ(h.faces.size(), s.faces.size());
  EXPECT_NEAR(mass_properties(h.mesh()).volume / mass_properties(s).volume, 1.0, 1e-12);
  for (const Face& f : h.faces) {
    const Vec3 c = (h.vertices[f[0]] + h.vertices[f[1]] + h.vertices[f[2]]) / 3;
    EXPECT_GT(face_normal(h, f).dot(c), 0);  // outward from the centre
  }
}

TEST(ConvexHull, GreedyAscentFindsTheSupportPoint) {
  // Points include interior ones and a box with coplanar faces (triangulated by "Qt").
  std::vector<Vec3> pts = random_points(400, 3);
  for (const Vec3& v : box_mesh(1.0, 1.0, 1.0).vertices) pts.push_back(v);
  for (const ConvexHull& h : {convex_hull(pts), convex_hull(icosphere(1.0, 2).vertices),
                              convex_hull(ellipsoid_mesh(3.0, 1.0, 0.5, 3).vertices)}) {
    std::mt19937 rng(11);
    std::normal_distribution<double> g;
    for (int trial = 0; trial < 200; ++trial) {
      const Vec3 d(g(rng), g(rng), g(rng));
      double best = -INFINITY;
      for (const Vec3& v : h.vertices) best = std::max(best, d.dot(v));
      Index at = 0;
      for (bool moved = true; moved;) {
        moved = false;
        for (Index w : neighbours(h, at)) {
          if (d.dot(h.vertices[w]) > d.dot(h.vertices[at])) {
            at = w;
            moved = true;
          }
        }
      }
      EXPECT_NEAR(d.dot(h.vertices[at]), best, 1e-12 * d.norm());
    }
  }
}

TEST(ConvexHull, BadInputRefused) {
  const std::vector<Vec3> three{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  EXPECT_CONTAINS(test::input_error_of([&] { convex_hull(three); }), "at least 4");
  std::vector<Vec3> flat;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j) flat.emplace_back(i, j * 0.5, 2.0);
  EXPECT_CONTAINS(test::input_error_of([&] { convex_hull(flat); }), "coplanar");
  std::vector<Vec3> line;
  for (int i = 0; i < 6; ++i) line.emplace_back(i, 2 * i, -i);
  EXPECT_CONTAINS(test::input_error_of([&] { convex_hull(line); }), "coplanar");
  const std::vector<Vec3> same(6, Vec3(1, 2, 3));
  EXPECT_CONTAINS(test::input_error_of([&] { convex_hull(same); }), "all 6 points coincide");
  std::vector<Vec3> nan = random_points(10, 1);
  nan[4].y() = std::nan("");
  EXPECT_CONTAINS(test::input_error_of([&] { convex_hull(nan); }), "point 4 is not finite");
}

TEST(ConvexHull, IsConvex) {
  EXPECT_TRUE(is_convex(box_mesh(1, 2, 3), 1e-12));
  EXPECT_TRUE(is_convex(icosphere(1, 3), 1e-12));
  EXPECT_TRUE(is_convex(convex_hull(random_points(200, 5)).mesh(), 1e-12));
  TriMesh dented = box_mesh(1, 1, 1);
  dented.vertices[7] *= 0.5;  // pull a corner in
  EXPECT_FALSE(is_convex(dented, 1e-6));
}

}  // namespace
}  // namespace grainlab
