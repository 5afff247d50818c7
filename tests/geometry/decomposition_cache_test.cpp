// decompose_convex_cached (decomposition_cache.h): a mesh seen before is
// looked up, not decomposed again, and the lookup returns exactly what
// decompose_convex gives (every point's bits, every cell plane); a mesh that
// differs in one bit, or other options, is decomposed anew.
#include "geometry/decomposition_cache.h"
#include "geometry/primitives.h"
#include "test_helpers.h"

#include <gtest/gtest.h>

#include <cstring>

using namespace grainlab;

namespace {

using test::u_prism;

void expect_same_bits(const ConvexDecomposition& a, const ConvexDecomposition& b) {
  ASSERT_EQ(a.pieces.size(), b.pieces.size());
  for (std::size_t k = 0; k < a.pieces.size(); ++k) {
    ASSERT_EQ(a.pieces[k].size(), b.pieces[k].size());
    EXPECT_EQ(std::memcmp(a.pieces[k].data(), b.pieces[k].data(), a.pieces[k].size() * sizeof(Vec3)), 0);
    ASSERT_EQ(a.cells[k].size(), b.cells[k].size());
    for (std::size_t j = 0; j < a.cells[k].size(); ++j) {
      EXPECT_EQ(a.cells[k][j].n, b.cells[k][j].n);
      EXPECT_EQ(a.cells[k][j].c, b.cells[k][j].c);
    }
  }
  EXPECT_EQ(a.volume, b.volume);
  EXPECT_EQ(a.hull_volume, b.hull_volume);
  EXPECT_EQ(a.pieces_volume, b.pieces_volume);
}

}  // namespace

TEST(DecompositionCache, ASecondRequestIsLookedUpAndIdentical) {
  clear_decomposition_cache();
  const TriMesh mesh = u_prism();
  const ConvexDecomposition direct = decompose_convex(mesh);
  const ConvexDecomposition first = decompose_convex_cached(mesh);
  EXPECT_EQ(decomposition_cache_stats().misses, 1u);
  const ConvexDecomposition second = decompose_convex_cached(mesh);
  const DecompositionCacheStats s = decomposition_cache_stats();
  EXPECT_EQ(s.misses, 1u);
  EXPECT_EQ(s.hits, 1u);
  EXPECT_EQ(s.entries, 1u);
  EXPECT_GT(direct.pieces.size(), 1u);  // concave: several pieces
  expect_same_bits(direct, first);
  expect_same_bits(direct, second);
}

TEST(DecompositionCache, AnotherMeshOrOtherOptionsAreDecomposedAnew) {
  clear_decomposition_cache();
  const TriMesh mesh = u_prism();
  decompose_convex_cached(mesh);
  TriMesh moved = mesh;
  moved.vertices[0].x() = std::nextafter(moved.vertices[0].x(), 1e9);  // one bit
  const ConvexDecomposition other = decompose_convex_cached(moved);
  expect_same_bits(decompose_convex(moved), other);
  DecompositionOptions two;
  two.max_pieces = 2;
  const ConvexDecomposition fewer = decompose_convex_cached(mesh, two);
  EXPECT_EQ(fewer.pieces.size(), 2u);
  const DecompositionCacheStats s = decomposition_cache_stats();
  EXPECT_EQ(s.misses, 3u);
  EXPECT_EQ(s.hits, 0u);
  EXPECT_EQ(s.entries, 3u);
  clear_decomposition_cache();
  EXPECT_EQ(decomposition_cache_stats().entries, 0u);
}
