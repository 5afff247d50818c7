// Narrowphase routines: exact where a closed form exists, GJK/EPA otherwise.
// All return a ContactResult whose normal points from the first shape to the second.
#pragma once

#include "collision/contact_result.h"
#include "collision/shapes.h"

namespace grainlab {

// Exact sphere-sphere.
ContactResult collide(const SphereShape& a, const SphereShape& b);
// Exact plane-sphere; normal = plane normal.
ContactResult collide(const PlaneShape& a, const SphereShape& b);
// Exact plane-polytope: depth of the deepest vertex; contact point at the
// depth-weighted centroid of all penetrating vertices (so a face lying flat on
// the plane pushes at its middle), moved to halfway between the surfaces.
ContactResult collide(const PlaneShape& a, const PolytopeShape& b);

// General convex pair by GJK (separation) and EPA (penetration).
// `dir` is the warm-start search direction (e.g. last step's normal for this
// pair, any non-zero vector the first time); it is updated for the next call.
// `warm` says dir is this pair's normal from the previous step: then a
// shallow penetration is found by the local translated-GJK iteration
// (penetration.h), several times cheaper than EPA; cold calls use EPA.
ContactResult collide_convex(const PolytopeShape& a, const PolytopeShape& b, Vec3& dir, bool warm = false);
ContactResult collide_convex(const SphereShape& a, const PolytopeShape& b, Vec3& dir);
ContactResult collide_convex(const BoxShape& a, const PolytopeShape& b, Vec3& dir, bool warm = false);
ContactResult collide_convex(const BoxShape& a, const SphereShape& b, Vec3& dir);

}  // namespace grainlab
