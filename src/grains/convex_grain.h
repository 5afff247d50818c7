// Simple convex grains for scenes, tests and benchmarks: the convex hull of
// points spread evenly (Fibonacci lattice) over a randomly proportioned,
// slightly bumpy ellipsoid. n points in convex position give a hull of
// 2n - 4 triangles (Euler), so n = 1002 gives the paper's 2000 faces.
// (Grains with controlled roundness are the grains issue's generator.)
#pragma once

#include "core/rng.h"
#include "geometry/trimesh.h"

namespace grainlab {

struct ConvexGrainSpec {
  double equivalent_radius = 0.5e-3;  // m: radius of the sphere of equal volume
  int points = 1002;                   // hull vertices before bumps (about 2n-4 faces)
  double elongation = 0.85;           // intermediate / long axis (mean; +-0.05 random)
  double flatness = 0.75;             // short / intermediate axis (mean; +-0.05 random)
  double bumpiness = 0.03;            // relative radial noise
};

// A closed, outward, convex triangle mesh centred near the origin, scaled so its
// volume is that of a sphere of `equivalent_radius`.
TriMesh convex_grain(const ConvexGrainSpec& spec, Rng& rng);

}  // namespace grainlab
