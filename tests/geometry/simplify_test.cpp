// Simplification keeps meshes closed and their volume within 1 %.
#include "geometry/simplify.h"

#include "core/rng.h"
#include "geometry/mass_properties.h"
#include "geometry/mesh_check.h"
#include "geometry/primitives.h"
#include "geometry/rounded_hull.h"
#include "test_helpers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace grainlab {
namespace {

void expect_simplified(const TriMesh& in, int budget, const char* what) {
  const double v0 = mass_properties(in).volume;
  const SimplifyResult r = simplify_mesh(in, budget);
  EXPECT_TRUE(r.within_budget) << what;
  EXPECT_LE(static_cast<int>(r.mesh.faces.size()), budget) << what;
  EXPECT_GT(r.mesh.faces.size(), 0.5 * budget) << what;
  const MeshCheck c = check_mesh(r.mesh);
  EXPECT_TRUE(c.ok()) << what << ": " << c.describe();
  EXPECT_EQ(c.open_edges, 0) << what;
  const double v = mass_properties(r.mesh).volume;
  EXPECT_NEAR(v, v0, 0.01 * v0) << what;
  EXPECT_NEAR(r.volume_error, std::abs(v - v0) / v0, 1e-12) << what;
  std::printf("%s: %zu -> %zu faces, volume error %.4f %%\n", what, in.faces.size(), r.mesh.faces.size(),
              100 * r.volume_error);
}

TEST(Simplify, FineSphereToTwoThousandFaces) { expect_simplified(icosphere(1e-3, 5), 2000, "icosphere(5)"); }

TEST(Simplify, FineEllipsoidToTwoThousandFaces) {
  expect_simplified(ellipsoid_mesh(2.0, 1.0, 0.6, 5), 2000, "ellipsoid");
}

// 500 faces cannot hold an elongated ellipsoid's volume within 1 % (the kept
// vertices lie on the surface, so the facets cut inside): the budget grows.
TEST(Simplify, BudgetGrowsWhenVolumeCannotBeKept) {
  const TriMesh in = ellipsoid_mesh(2.0, 1.0, 0.6, 5);
  const double v0 = mass_properties(in).volume;
  const SimplifyResult r = simplify_mesh(in, 500);
  EXPECT_FALSE(r.within_budget);
  EXPECT_GT(r.target_faces, 500);
  EXPECT_LT(r.mesh.faces.size(), in.faces.size());
  EXPECT_TRUE(check_mesh(r.mesh).ok());
  EXPECT_NEAR(mass_properties(r.mesh).volume, v0, 0.01 * v0);
}

TEST(Simplify, FineRoundedPolytopeToTwoThousandFaces) {
  Rng rng(3);
  std::vector<Vec3> core;
  for (int i = 0; i < 20; ++i) core.push_back(rng.unit_vector().cwiseProduct(Vec3(1.0, 0.8, 0.6)));
  expect_simplified(rounded_hull_mesh(core, 0.15, 20000), 2000, "rounded polytope");
}

TEST(Simplify, MeshWithinBudgetIsReturnedUnchanged) {
  const TriMesh m = icosphere(1.0, 2);  // 320 faces
  const SimplifyResult r = simplify_mesh(m, 2000);
  EXPECT_EQ(r.mesh.faces, m.faces);
  EXPECT_EQ(r.volume_error, 0.0);
  EXPECT_TRUE(r.within_budget);
}

TEST(Simplify, RejectsATinyBudget) {
  EXPECT_CONTAINS(test::input_error_of([] { simplify_mesh(icosphere(1.0, 1), 2); }), "face budget");
}

}  // namespace
}  // namespace grainlab
