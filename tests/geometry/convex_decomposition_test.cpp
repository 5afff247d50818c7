// decompose_convex (convex_decomposition.h): a convex mesh is its own single
// piece; a U-shaped prism splits into its three bars with almost nothing of
// the cavity filled; a dented grain's pieces cover every point of its surface
// and fill in much less of the dents than its hull. The volumes are exact
// (the hulls' and the meshes' own), so the bounds hold for the method, not
// for a sampling.
#include "core/error.h"
#include "core/rng.h"
#include "geometry/convex_decomposition.h"
#include "geometry/convex_hull.h"
#include "geometry/primitives.h"
#include "grains/generator.h"
#include "test_helpers.h"

#include <gtest/gtest.h>

using namespace grainlab;

namespace {

// Outward planes of each piece's hull.
struct Planes {
  std::vector<Vec3> n;
  std::vector<double> d;
};

std::vector<Planes> piece_planes(const ConvexDecomposition& dec) {
  std::vector<Planes> out;
  for (const auto& pts : dec.pieces) {
    const ConvexHull h = convex_hull(pts);
    Planes p;
    for (const Face& f : h.faces) {
      const Vec3 n = (h.vertices[f[1]] - h.vertices[f[0]]).cross(h.vertices[f[2]] - h.vertices[f[0]]);
      if (n.norm() == 0) continue;
      p.n.push_back(n.normalized());
      p.d.push_back(p.n.back().dot(h.vertices[f[0]]));
    }
    out.push_back(std::move(p));
  }
  return out;
}

// True if x lies in some piece, within tol.
bool covered(const std::vector<Planes>& pieces, const Vec3& x, double tol) {
  for (const Planes& p : pieces) {
    bool in = true;
    for (std::size_t k = 0; k < p.n.size() && in; ++k) in = p.n[k].dot(x) <= p.d[k] + tol;
    if (in) return true;
  }
  return false;
}

using test::u_prism;

}  // namespace

TEST(ConvexDecomposition, AConvexMeshIsOnePieceItsOwnHull) {
  for (const TriMesh& m : {box_mesh(1, 2, 3), ellipsoid_mesh(1, 0.7, 0.5, 3)}) {
    const ConvexDecomposition d = decompose_convex(m);
    ASSERT_EQ(d.pieces.size(), 1u);
    EXPECT_EQ(d.pieces[0].size(), m.vertices.size());
    EXPECT_NEAR(d.excess(), 0, 1e-9);
    EXPECT_NEAR(d.hull_excess(), 0, 1e-9);
  }
}

TEST(ConvexDecomposition, AUPrismSplitsIntoItsBars) {
  const TriMesh m = u_prism();
  const ConvexDecomposition d = decompose_convex(m);
  // Volume 10 x 2, hull 18 x 2: the hull fills in the cavity, 80 % more.
  EXPECT_NEAR(d.volume, 20, 1e-9);
  EXPECT_NEAR(d.hull_excess(), 0.8, 1e-9);
  EXPECT_LE(d.pieces.size(), 4u);
  EXPECT_LT(d.excess(), 0.02) << d.pieces.size() << " pieces";
  const std::vector<Planes> pieces = piece_planes(d);
  for (const Vec3& v : m.vertices) EXPECT_TRUE(covered(pieces, v, 1e-9)) << v.transpose();
  // The middle of the cavity is in no piece.
  EXPECT_FALSE(covered(pieces, Vec3(0, 2, 0), 0));
}

TEST(ConvexDecomposition, ADentedGrainsPiecesCoverItsSurfaceAndFillLessOfTheDents) {
  GeneratorSpec spec = preset_spec(GrainPreset::SubAngular);
  spec.faces = 400;
  spec.convexity = 0.85;
  Rng rng(11);
  const TriMesh m = generate_grain(spec, rng);
  const ConvexDecomposition d = decompose_convex(m);
  EXPECT_NEAR(d.hull_excess(), 1 / 0.85 - 1, 0.01);
  EXPECT_LE(d.pieces.size(), 8u);
  EXPECT_GE(d.pieces.size(), 2u);
  EXPECT_GT(d.excess(), 0);  // planes cannot follow a curved dent exactly
  EXPECT_LT(d.excess(), 0.5 * d.hull_excess()) << d.pieces.size() << " pieces";
  // Every vertex, and points inside every face, lie in a piece.
  const std::vector<Planes> pieces = piece_planes(d);
  const double tol = 1e-9;
  for (const Vec3& v : m.vertices) ASSERT_TRUE(covered(pieces, v, tol)) << v.transpose();
  for (const Face& f : m.faces) {
    const Vec3 c = (m.vertices[f[0]] + m.vertices[f[1]] + m.vertices[f[2]]) / 3;
    ASSERT_TRUE(covered(pieces, c, tol)) << c.transpose();
  }
}

TEST(ConvexDecomposition, BadOptionsAreRefused) {
  const TriMesh m = u_prism();
  DecompositionOptions o;
  o.max_pieces = 0;
  EXPECT_THROW(decompose_convex(m, o), InputError);
  o = {};
  o.grid = 2;
  EXPECT_THROW(decompose_convex(m, o), InputError);
  o = {};
  o.tolerance = -1;
  EXPECT_THROW(decompose_convex(m, o), InputError);
}

TEST(Prism, AClockwiseOrSelfCrossingPolygonIsRefused) {
  EXPECT_THROW(prism_mesh({{0, 0}, {0, 1}, {1, 0}}, 1), InputError);
  EXPECT_THROW(prism_mesh({{0, 0}, {1, 1}, {1, 0}, {0, 1}}, 1), InputError);
  const TriMesh m = u_prism();
  EXPECT_TRUE(!is_convex(m, 1e-6));
}
