// Spherical-harmonic coefficients of a grain mesh: the mesh's radial
// function about its volume centroid, projected onto Y_nm.
#pragma once

#include "geometry/spherical_harmonics.h"
#include "geometry/trimesh.h"

#include <string>

namespace grainlab {

struct ShFit {
  ShCoefficients coefficients;  // about `centre`, in the mesh's unit
  Vec3 centre = Vec3::Zero();   // the mesh's volume centroid: the origin of r(theta, phi)
  double rms_error = 0;         // RMS over the sphere of r_mesh - r_fit, in the mesh's unit
  double max_error = 0;         // largest |r_mesh - r_fit| at the quadrature's directions
  double equivalent_diameter = 0;  // the mesh's (6 V / pi)^(1/3), for relative errors
  int directions = 0;           // rays cast
};

// Casts rays from the mesh's centroid along the directions of
// sphere_quadrature(2 degree) (Gauss-Legendre x equal steps: (2 degree + 1)
// (4 degree + 1) rays) and projects the radii onto Y_nm, n <= degree: the
// least-squares fit over the sphere. Throws InputError naming `name` and the
// direction where a ray meets the surface more than once (the mesh is not
// star-shaped about its centroid). degree in 0..100.
ShFit fit_sh(const TriMesh& mesh, int degree, const std::string& name);

}  // namespace grainlab
