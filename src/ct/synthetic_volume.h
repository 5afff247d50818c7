// A synthetic X-ray CT scan of known grains, for tests and for trying the
// segmentation: grains of several shapes (ellipsoids, rounded and
// sub-angular polytopes from the grain generator, dented concave grains) at
// random positions and orientations, some pairs touching, voxelized with
// partial volume (voxelize.h), blurred like a scanner's point-spread function
// and given Gaussian noise.
#pragma once

#include "ct/volume.h"
#include "geometry/trimesh.h"

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace grainlab::ct {

struct SyntheticSpec {
  std::int64_t size = 144;          // voxels along each side (a cube)
  double voxel_size = 25e-6;        // m
  int grains = 8;
  int touching_pairs = 2;           // grains (0, 1), (2, 3), ... placed touching
  double grain_size = 36;           // voxels: mean intermediate dimension (+-15 %)
  std::uint64_t seed = 1;
  double blur = 1.0;                // voxels: Gaussian standard deviation
  double noise = 0.04;              // standard deviation, as a fraction of solid - pore
  float pore_level = 10000;         // grey level of air
  float solid_level = 40000;        // grey level of quartz
  int samples = 4;                  // sample lines per voxel side (partial volume)
};

// Throws InputError naming the field when the spec is impossible.
void validate(const SyntheticSpec& spec);

struct SyntheticGrain {
  std::string kind;   // "ellipsoid", "rounded", "sub-angular", "concave"
  TriMesh mesh;       // world coordinates (m), closed and outward
};

struct SyntheticScene {
  std::vector<SyntheticGrain> grains;
  std::vector<std::pair<int, int>> touching;  // indices into grains
  GreyVolume volume;                          // origin 0, spacing voxel_size, identity direction
};

// Builds the scene; the same spec gives the same volume, bit for bit. Throws
// RunError when the grains do not fit (fewer grains or a larger size helps).
SyntheticScene make_synthetic_scene(const SyntheticSpec& spec);

}  // namespace grainlab::ct
