// Closed, outward triangle meshes of simple solids, for tests and synthetic grains.
#pragma once

#include "geometry/trimesh.h"

#include <vector>

namespace grainlab {

// Axis-aligned box centred at the origin with half extents hx, hy, hz (8 vertices, 12 faces).
TriMesh box_mesh(double hx, double hy, double hz);

// Tetrahedron with the given corners, faces oriented outward whatever their order.
TriMesh tetrahedron_mesh(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

// Sphere of the given radius centred at the origin: an icosahedron with each face split
// into 4 `subdivisions` times (20 * 4^s faces), vertices on the sphere. s <= 8.
TriMesh icosphere(double radius, int subdivisions);

// Ellipsoid with semi-axes a, b, c along x, y, z: the unit icosphere scaled per axis.
TriMesh ellipsoid_mesh(double a, double b, double c, int subdivisions);

// Prism: a simple polygon in the xy plane (counter-clockwise, at least 3
// corners, convex or not) extruded from z = -half_depth to +half_depth; the
// caps are triangulated by ear clipping. Throws InputError for a polygon
// that is clockwise, degenerate or self-touching.
TriMesh prism_mesh(const std::vector<Vec2>& polygon, double half_depth);

}  // namespace grainlab
