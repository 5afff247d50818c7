// The kinds of collision shape, grains and walls alike: an id into the
// shape-pair table (dispatch.h), whose routines know what each kind's
// geometry is (PosedShape::geometry). The built-in kinds are named here; a
// new kind is registered (register_shape_kind in dispatch.h) and gets the
// next free id, so that adding one edits no enum.
#pragma once

#include <cstdint>

namespace grainlab {

enum class ShapeKind : std::uint8_t {
  Sphere = 0,    // grain: a sphere (no geometry: its radius is the body's)
  Polytope = 1,  // grain: a convex polytope (geometry: ConvexPolytope, the hull of a mesh)
  Plane = 2,     // wall: a half-space (no geometry)
  Box = 3,       // wall: a solid oriented box (geometry: Vec3, its half extents)
  Compound = 4,  // grain: a rigid union of convex pieces (geometry: CompoundShape, compound.h)
};

// Number of built-in kinds: the first registered kind's id.
inline constexpr int kBuiltInShapeKinds = 5;
// Most kinds, built-in and registered: the side of the shape-pair table.
inline constexpr int kMaxShapeKinds = 16;

}  // namespace grainlab
