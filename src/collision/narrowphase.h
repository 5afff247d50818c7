// Narrowphase routines: exact where a closed form exists, GJK/EPA otherwise.
// All return a ContactResult whose normal points from the first shape to the second.
#pragma once

#include "collision/contact_result.h"
#include "collision/shapes.h"
#include "collision/simplex_cache.h"

namespace grainlab {

// Exact sphere-sphere (sphere_pairs.h: every sphere pair's geometry is
// computed by one function, so that every path gives a pair the same bits).
ContactResult collide(const SphereShape& a, const SphereShape& b);
// Exact plane-sphere; normal = plane normal.
ContactResult collide(const PlaneShape& a, const SphereShape& b);
// Exact plane-polytope: the soft depth of the vertices below the plane
// (soft_depth.h): depth D, gain and the point on the line of action of the
// conservative force (a face lying flat on the plane pushes at its middle).
ContactResult collide(const PlaneShape& a, const PolytopeShape& b);
// Exact box-sphere (box_sphere.cpp); normal from the box to the sphere.
ContactResult collide(const BoxShape& a, const SphereShape& b);

// General convex pair by GJK (separation) and EPA (penetration).
// `dir` is the warm-start search direction (e.g. last step's normal for this
// pair, any non-zero vector the first time); it is updated for the next call.
// `warm` says dir is this pair's normal from the previous step: then a
// shallow penetration is found by the local translated-GJK iteration
// (penetration.h), several times cheaper than EPA; cold calls use EPA.
// A touching polytope pair's contact is then contact_patch's below.
// `simplex` (optional): the pair's kept GJK simplex (simplex_cache.h).
ContactResult collide_convex(const PolytopeShape& a, const PolytopeShape& b, Vec3& dir, bool warm = false,
                             SimplexCache* simplex = nullptr);
ContactResult collide_convex(const SphereShape& a, const PolytopeShape& b, Vec3& dir);

// For touching polytopes A, B with r's normal and penetration depth: replaces
// r by the soft depth of the vertices of each body lying inside the other
// (soft_depth.h: depth, normal, point, gain, twist, spread) when that depth
// exceeds r's; keeps the witness point otherwise (e.g. edge across edge).
void contact_patch(const PolytopeShape& a, const PolytopeShape& b, ContactResult& r);
ContactResult collide_convex(const BoxShape& a, const PolytopeShape& b, Vec3& dir, bool warm = false);
ContactResult collide_convex(const BoxShape& a, const SphereShape& b, Vec3& dir);

}  // namespace grainlab
