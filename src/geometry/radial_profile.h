// The distance from a point to a closed mesh's surface along given
// directions: the radial function r(u) of a grain that is star-shaped about
// the point.
#pragma once

#include "geometry/trimesh.h"

#include <span>
#include <string>
#include <vector>

namespace grainlab {

// For each unit direction u, the distance t > 0 at which the ray origin + t u
// leaves the mesh. Throws InputError naming `name` and the direction
// (theta, phi in degrees) where a ray crosses the surface more than once (the
// mesh is not star-shaped about `origin`: a spherical-harmonic surface cannot
// describe it) or never (the origin is outside). Crossings closer than 1e-9
// of the mesh's size (a ray through an edge or a vertex) count as one.
std::vector<double> radial_profile(const TriMesh& mesh, const Vec3& origin, std::span<const Vec3> directions,
                                   const std::string& name);

}  // namespace grainlab
