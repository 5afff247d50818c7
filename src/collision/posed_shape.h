// What the shape-pair table (dispatch.h) works on: a shape of any kind placed
// in the world, the per-pair warm-start cache, and the contacts a routine
// writes. World builds these from its Model and State without looking at the
// kind: the pose is common to every kind, and what a kind has of its own
// (a polytope's hull, a compound's pieces, a box's half extents) is behind
// one pointer that only the routines registered for the kind read.
#pragma once

#include "collision/contact_result.h"
#include "collision/shape_kind.h"
#include "collision/simplex_cache.h"
#include "core/types.h"

#include <cstdint>

namespace grainlab {

// A shape in the world: p_world = pos + rot * (scale * p_local).
struct PosedShape {
  ShapeKind kind = ShapeKind::Sphere;
  // The kind's own geometry in its local frame at scale 1 (shape_kind.h says
  // its type; null for a kind that has none), shared, never owned here.
  const void* geometry = nullptr;
  double radius = 0;          // the body's radius (m): a sphere's; else its volume-equivalent radius
  const Mat3* rot = nullptr;  // local-to-world rotation
  const Quat* q = nullptr;    // the same rotation as a quaternion (Plane: normal = q * z)
  Vec3 pos = Vec3::Zero();    // centre of mass / wall point (m)
  double scale = 1;           // uniform scale of the local geometry

  // The geometry as the kind's type T, for the kind's own routines (which
  // are registered only for kinds whose geometry is a T).
  template <class T>
  const T& geometry_as() const {
    return *static_cast<const T*>(geometry);
  }
};

// Warm-start data of one candidate pair, kept from step to step while the
// broadphase keeps the pair (its routines read and update it).
struct PairCache {
  Vec3 dir = Vec3::UnitX();      // GJK search direction: last normal, a to b
  Index hint_a = 0, hint_b = 0;  // support-vertex hints of the two shapes
  bool warm = false;             // dir and hints come from a previous step
  SimplexCache simplex;          // polytope pairs: the last GJK simplex (simplex_cache.h)
};

// A sub-contact of a pair: its geometry and its id within the pair (0 for a
// pair of convex shapes, which touch at one place at most).
struct SubContact {
  ContactResult geo;
  std::int32_t sub = 0;
};

// Most sub-contacts one pair routine may write.
inline constexpr int kMaxSubContacts = 8;

}  // namespace grainlab
