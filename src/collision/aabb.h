// Axis-aligned bounding boxes.
#pragma once

#include "core/types.h"

namespace grainlab {

struct Aabb {
  Vec3 lo = Vec3::Zero();
  Vec3 hi = Vec3::Zero();

  bool overlaps(const Aabb& o) const {
    return lo.x() <= o.hi.x() && o.lo.x() <= hi.x() && lo.y() <= o.hi.y() &&
           o.lo.y() <= hi.y() && lo.z() <= o.hi.z() && o.lo.z() <= hi.z();
  }
  Aabb inflated(double margin) const {
    return {lo.array() - margin, hi.array() + margin};
  }
};

}  // namespace grainlab
