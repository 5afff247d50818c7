// Sphere-swept convex polytopes: the Minkowski sum of a convex point set with a
// ball, tessellated to a chosen face count. Used for synthetic grains with
// rounded corners and for test shapes (a cube with rounded corners).
#pragma once

#include "geometry/trimesh.h"

#include <span>
#include <vector>

namespace grainlab {

// n unit vectors spread evenly over the sphere (Fibonacci lattice), n >= 4.
std::vector<Vec3> fibonacci_directions(int n);

// The closed, outward mesh of hull(core) + ball(radius), sampled along
// `faces / 2 + 2` directions: for each direction u the surface point
// support(core, u) + radius u. With radius > 0 every sample is an extreme point,
// so the hull of the samples has exactly 2 n - 4 = `faces` triangles (Euler).
// Corners are spherical patches of radius `radius`, edges cylindrical strips,
// facets flat. radius == 0 gives the plain hull of the core (fewer faces).
// Throws InputError for a negative radius, faces < 8, or fewer than one core point.
TriMesh rounded_hull_mesh(std::span<const Vec3> core, double radius, int faces);

}  // namespace grainlab
