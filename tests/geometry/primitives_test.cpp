// Primitives are closed, manifold, outward and have the requested size.
#include "geometry/primitives.h"

#include "geometry/mass_properties.h"
#include "geometry/mesh_check.h"
#include "test_helpers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace grainlab {
namespace {

TEST(Primitives, BoxIsClosedOutwardWithTwelveFaces) {
  const TriMesh m = box_mesh(0.5, 1.0, 1.5);
  EXPECT_EQ(m.vertices.size(), 8u);
  EXPECT_EQ(m.faces.size(), 12u);
  const MeshCheck c = check_mesh(m);
  EXPECT_TRUE(c.ok()) << c.describe();
  EXPECT_EQ(c.degenerate_faces, 0);
  EXPECT_NEAR(c.signed_volume, 1.0 * 2.0 * 3.0, 1e-12);
}

TEST(Primitives, TetrahedronOutwardInEitherCornerOrder) {
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0), d(0, 0, 1);
  for (const TriMesh& m : {tetrahedron_mesh(a, b, c, d), tetrahedron_mesh(a, c, b, d)}) {
    const MeshCheck k = check_mesh(m);
    EXPECT_TRUE(k.ok()) << k.describe();
    EXPECT_NEAR(k.signed_volume, 1.0 / 6.0, 1e-15);
  }
  EXPECT_CONTAINS(test::input_error_of([&] { tetrahedron_mesh(a, b, c, Vec3(1, 1, 0)); }), "coplanar");
}

TEST(Primitives, IcosphereCountsRadiusAndValidity) {
  for (int s = 0; s <= 3; ++s) {
    const TriMesh m = icosphere(2.0, s);
    const std::size_t f = 20 * static_cast<std::size_t>(std::pow(4, s));
    EXPECT_EQ(m.faces.size(), f);
    EXPECT_EQ(m.vertices.size(), f / 2 + 2);  // Euler: V = F/2 + 2 for a closed triangulated sphere
    for (const Vec3& v : m.vertices) EXPECT_NEAR(v.norm(), 2.0, 1e-14);
    const MeshCheck c = check_mesh(m);
    EXPECT_TRUE(c.ok()) << c.describe();
    EXPECT_EQ(c.components, 1);
  }
  EXPECT_CONTAINS(test::input_error_of([] { icosphere(-1.0, 2); }), "radius");
  EXPECT_CONTAINS(test::input_error_of([] { icosphere(1.0, 9); }), "subdivisions");
}

TEST(Primitives, EllipsoidVerticesOnTheSurface) {
  const TriMesh m = ellipsoid_mesh(3.0, 2.0, 1.0, 2);
  for (const Vec3& v : m.vertices) {
    EXPECT_NEAR(std::pow(v.x() / 3.0, 2) + std::pow(v.y() / 2.0, 2) + std::pow(v.z(), 2), 1.0, 1e-13);
  }
  const MeshCheck c = check_mesh(m);
  EXPECT_TRUE(c.ok()) << c.describe();
  EXPECT_LT(c.signed_volume, 4.0 / 3.0 * std::numbers::pi * 6.0);
  EXPECT_GT(c.signed_volume, 0.9 * 4.0 / 3.0 * std::numbers::pi * 6.0);
}

}  // namespace
}  // namespace grainlab
