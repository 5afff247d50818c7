// Exact mass properties of a closed triangle mesh (divergence theorem).
#pragma once

#include "geometry/trimesh.h"

namespace grainlab {

// Per unit density: multiply `inertia` and `principal_moments` by the density
// (kg/m^3) to get kg m^2.
struct MassProperties {
  double volume = 0;            // m^3
  Vec3 centroid = Vec3::Zero(); // m
  Mat3 inertia = Mat3::Zero();  // about the centroid, world axes, m^5
  Vec3 principal_moments = Vec3::Zero();  // ascending, m^5
  Mat3 principal_axes = Mat3::Identity(); // columns; right-handed; inertia = A diag(moments) A^T
};

// Exact for any closed, consistently outward-oriented mesh.
MassProperties mass_properties(const TriMesh& mesh);

}  // namespace grainlab
