// Taubin's lambda|mu smoothing of a triangle mesh (Taubin 1995).
//
// One Laplacian step moves each vertex towards the mean of its edge
// neighbours: p <- p + k (mean(q) - p). With k = lambda > 0 alone this is a
// low-pass filter that also shrinks the mesh; Taubin alternates a step with
// lambda and one with mu < -lambda, whose transfer function
// (1 - lambda k_f)(1 - mu k_f) is about 1 at low surface frequencies k_f
// (below the pass band k_PB = 1/lambda + 1/mu, here 0.1) and below 1 above it:
// the voxel staircase and noise go, the shape and volume stay.
#pragma once

#include "geometry/trimesh.h"

namespace grainlab::ct {

// `iterations` lambda|mu pairs, in place. Connectivity is unchanged.
void taubin_smooth(TriMesh& mesh, int iterations, double lambda = 0.5, double mu = -0.53);

}  // namespace grainlab::ct
