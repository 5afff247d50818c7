// The kinds of collision shape, grains and walls alike. Each kind has its own
// support map / routines (shapes.h, narrowphase.h) and one row of routines in
// the shape-pair table (dispatch.cpp). A new kind: add it here (before Count),
// write its routines in their own file, register them in dispatch.cpp.
#pragma once

#include <cstdint>

namespace grainlab {

enum class ShapeKind : std::uint8_t {
  Sphere = 0,    // grain: a sphere
  Polytope = 1,  // grain: a convex polytope (hull of a mesh)
  Plane = 2,     // wall: a half-space
  Box = 3,       // wall: a solid oriented box
  Compound = 4,  // grain: a rigid union of convex pieces (compound.h)
  Count          // number of kinds (table size), not a kind
};

// Number of shape kinds: the side of the shape-pair table.
inline constexpr int kShapeKindCount = static_cast<int>(ShapeKind::Count);

}  // namespace grainlab
