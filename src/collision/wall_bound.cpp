// Broadphase bounds of the wall kinds (see wall_bound.h).
#include "collision/wall_bound.h"

#include <stdexcept>

namespace grainlab {

WallBound wall_bound(const PosedShape& wall) {
  WallBound b;
  switch (wall.kind) {
    case ShapeKind::Plane:
      b.half_space = true;
      b.point = wall.pos;
      b.normal = *wall.q * Vec3::UnitZ();
      return b;
    case ShapeKind::Box: {
      const Vec3 ext = wall.rot->cwiseAbs() * wall.geometry_as<Vec3>();  // half extents
      b.box = {wall.pos - ext, wall.pos + ext};
      return b;
    }
    default: throw std::logic_error("wall_bound: not a wall shape kind");
  }
}

}  // namespace grainlab
