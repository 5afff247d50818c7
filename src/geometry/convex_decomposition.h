// Approximate convex decomposition of a closed (possibly concave) mesh by
// plane cuts: the collision shape of a concave grain (issue 12). Mass
// properties always come from the exact mesh; this only gives the pieces
// that touch other grains.
//
// A piece is the convex hull of the part of the mesh's surface that lies in
// one cell of a binary space partition by planes. The cells are disjoint, so
// the pieces' hulls are disjoint too, and every point of the surface lies in
// some piece: the union of the pieces contains the grain (nothing missing)
// and exceeds it by   excess = sum_k V(hull_k) - V(mesh)   (the part of the
// dents still filled in). The convex hull of the whole grain is the one-piece
// case, with excess V(hull) - V(mesh) = V (1/C - 1), C the convexity.
//
// Cuts are chosen greedily: the piece with the largest excess is split by the
// plane that minimises V(hull_left) + V(hull_right), searched over the
// piece's principal directions and their diagonals at several offsets, then
// refined; a piece's own volume (for its excess) is counted on a voxel grid
// of the mesh, scaled so that the grid gives the mesh's exact volume.
// Splitting stops at max_pieces, or when the excess is below
// tolerance * V(mesh), or when no cut lowers it by a useful amount.
#pragma once

#include "geometry/trimesh.h"

#include <vector>

namespace grainlab {

struct DecompositionOptions {
  int max_pieces = 8;        // at most this many pieces (>= 1)
  double tolerance = 0.01;   // stop when the excess is below this fraction of the mesh volume
  int grid = 48;             // voxels along the mesh's longest side (for the pieces' own volumes)
};

// The half-space n.p <= c (n unit).
struct HalfSpace {
  Vec3 n = Vec3::UnitZ();
  double c = 0;
};

struct ConvexDecomposition {
  std::vector<std::vector<Vec3>> pieces;  // each piece's points (its hull is the piece), mesh units
  std::vector<std::vector<HalfSpace>> cells;  // each piece's cell (empty for a single piece): disjoint, tiling space
  double volume = 0;                      // exact volume of the mesh
  double hull_volume = 0;                 // volume of the whole mesh's convex hull
  double pieces_volume = 0;               // sum of the pieces' hull volumes (>= volume)
  // Excess of the pieces over the mesh, as a fraction of its volume.
  double excess() const { return pieces_volume / volume - 1; }
  // Same for the single convex hull: 1/C - 1.
  double hull_excess() const { return hull_volume / volume - 1; }
};

// Decomposes a closed, outward mesh (check_mesh passes). A convex mesh gives
// one piece, its own hull. Throws InputError for bad options or a mesh
// without volume.
ConvexDecomposition decompose_convex(const TriMesh& mesh, const DecompositionOptions& options = {});

}  // namespace grainlab
