// Closed meshes to partial-volume voxel occupancy, and a Gaussian blur: the
// two optical steps of a synthetic CT scan.
//
// Occupancy of voxel (i, j, k) (the cube [i-1/2, i+1/2] x ... in index
// coordinates) is the fraction of it inside the mesh. Each voxel row along x
// is sampled by s x s lines parallel to x (at sub-voxel offsets in y and z);
// along each line the crossings with the mesh are found exactly, sorted, and
// the inside intervals (between the 1st and 2nd crossing, 3rd and 4th, ...:
// the parity rule, right for any closed mesh, concave included) are added to
// the voxels they pass, by length. So x is exact and y, z are sampled s^2
// times. Lines are offset by 1e-7 voxel so they never pass exactly through a
// mesh edge or vertex.
#pragma once

#include "ct/volume.h"
#include "geometry/trimesh.h"

namespace grainlab::ct {

// Adds `mesh`'s occupancy (vertices in voxel-index coordinates) to `occupancy`
// with `samples` x `samples` lines per voxel row. Parts outside the grid are cut.
void add_occupancy(const TriMesh& mesh, int samples, GreyVolume& occupancy);

// True when `p` (same coordinates as the mesh) is inside the closed mesh (parity of crossings along +x).
bool inside_mesh(const TriMesh& mesh, const Vec3& p);

// Separable Gaussian blur with standard deviation `sigma` voxels (kernel
// radius ceil(3 sigma), edges replicated). sigma <= 0 leaves the volume as is.
void gaussian_blur(GreyVolume& volume, double sigma);

}  // namespace grainlab::ct
