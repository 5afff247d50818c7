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

// One convex piece of a compound.
struct CompoundPiece {
  ShapeKind kind = ShapeKind::Sphere;  // Sphere or Polytope
  Vec3 offset = Vec3::Zero();          // piece origin in the compound's frame (m at scale 1)
  double radius = 0;                   // Sphere: radius at scale 1 (m)
  ConvexPolytope hull;                 // Polytope: vertices about `offset`, compound's axes
};

// A compound: at most kMaxCompoundPieces pieces (each can touch a convex
// neighbour once, and every sub-contact needs a slot in the narrowphase).
struct CompoundShape {
  std::vector<CompoundPiece> pieces;
};

// Most pieces a compound may have.
inline constexpr int kMaxCompoundPieces = 8;

}  // namespace grainlab
