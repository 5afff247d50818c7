// Compound shapes: a rigid union of convex pieces (spheres and polytopes),
// the collision shape of a grain that is not convex (issue 12 decomposes
// scanned concave grains into such pieces). Pieces are placed in the
// compound's local frame: p_local = offset + q_piece, q_piece in the piece's
// own (unrotated) coordinates, so a posed piece is
//   pos_piece = pos + rot * (scale * offset),  rot and scale of the compound.
// Contacts are per piece (routines_compound.cpp): against a convex shape the
// sub-contact id is the piece index; compound against compound it is
// i * (pieces of b) + j. Each piece pair is collided cold (no warm start).
#pragma once

#include "collision/shape_kind.h"
#include "collision/shapes.h"
#include "core/types.h"

#include <vector>

namespace grainlab {

// A half-space n.p <= c of the compound's frame (p in m at scale 1; n unit).
struct CellPlane {
  Vec3 n = Vec3::UnitZ();
  double c = 0;
};

// One convex piece of a compound.
struct CompoundPiece {
  ShapeKind kind = ShapeKind::Sphere;  // Sphere or Polytope
  Vec3 offset = Vec3::Zero();          // piece origin in the compound's frame (m at scale 1)
  double radius = 0;                   // Sphere: radius at scale 1 (m)
  ConvexPolytope hull;                 // Polytope: vertices about `offset`, compound's axes
  // The cell of a concave grain's piece (convex_decomposition.h): the cells
  // of a grain's pieces tile space without overlap, and a piece owns the
  // contacts whose point lies in its cell. Where the surface of one face runs
  // across two pieces, a neighbour pressing there meets both pieces with the
  // full depth; ownership keeps one of the two contacts, not twice the force.
  // Empty: the piece owns every contact (clusters of spheres).
  std::vector<CellPlane> cell;
};

// A compound: at most kMaxCompoundPieces pieces (each can touch a convex
// neighbour once, and every sub-contact needs a slot in the narrowphase).
struct CompoundShape {
  std::vector<CompoundPiece> pieces;
};

// Most pieces a compound may have.
inline constexpr int kMaxCompoundPieces = 8;

}  // namespace grainlab
