// A wall's broadphase test: may a grain's bounding sphere touch the wall?
// Prepared once per wall and step, then asked for every grain. Half-spaces
// (Plane) compare the sphere's signed distance with its radius; solid walls
// (Box) compare axis-aligned boxes (the oriented box's AABB: half extents
// |R| h).
#pragma once

#include "collision/aabb.h"
#include "collision/posed_shape.h"

namespace grainlab {

struct WallBound {
  bool half_space = false;           // Plane: test the signed distance; else the AABB
  Vec3 point = Vec3::Zero();         // a point on the plane (m)
  Vec3 normal = Vec3::UnitZ();       // outward unit normal
  Aabb box;                          // AABB of a solid wall

  // True if a sphere at x of radius r may touch the wall.
  bool may_touch(const Vec3& x, double r) const {
    return half_space ? normal.dot(x - point) < r : box.overlaps(Aabb{x.array() - r, x.array() + r});
  }
};

// The broadphase bound of a wall shape (Plane or Box); throws std::logic_error for a grain kind.
WallBound wall_bound(const PosedShape& wall);

}  // namespace grainlab
