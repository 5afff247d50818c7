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
// Exact box-sphere (box_sphere.cpp); normal from the box to the sphere.
ContactResult collide(const BoxShape& a, const SphereShape& b);

// General convex pair by GJK (separation) and EPA (penetration).
// `dir` is the warm-start search direction (e.g. last step's normal for this
// pair, any non-zero vector the first time); it is updated for the next call.
// `warm` says dir is this pair's normal from the previous step: then a
// shallow penetration is found by the local translated-GJK iteration
// (penetration.h), several times cheaper than EPA; cold calls use EPA.
// The contact point of a touching polytope pair is not the witness point but
// the patch centroid of contact_patch below (with ContactResult::spread).
ContactResult collide_convex(const PolytopeShape& a, const PolytopeShape& b, Vec3& dir, bool warm = false);
ContactResult collide_convex(const SphereShape& a, const PolytopeShape& b, Vec3& dir);

// For touching polytopes A, B with r's normal: replaces r.point by the centroid
// of the vertices of each body lying inside the other, weighted by their depth
// inside it (continuous in the configuration: a vertex entering the overlap
// has weight 0), moved to halfway between the two supporting planes, and sets
// r.spread to their weighted tangential variance about it. Keeps the witness
// point if no vertex lies inside the other body (e.g. edge across edge).
void contact_patch(const PolytopeShape& a, const PolytopeShape& b, ContactResult& r);
ContactResult collide_convex(const BoxShape& a, const PolytopeShape& b, Vec3& dir, bool warm = false);
ContactResult collide_convex(const BoxShape& a, const SphereShape& b, Vec3& dir);

}  // namespace grainlab
