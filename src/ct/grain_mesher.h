// One grain of a labelled CT volume to a closed, checked triangle mesh in
// world coordinates (m): iso-surface, Taubin smoothing, simplification to a
// face budget, mesh check.
#pragma once

#include "ct/regions.h"
#include "ct/volume.h"
#include "geometry/trimesh.h"

#include <optional>

namespace grainlab::ct {

// How grain surfaces are placed.
struct MeshingOptions {
  int faces = 2000;           // face budget after simplification
  int smooth_iterations = 10; // Taubin lambda|mu pairs
  double denoise = 0.7;       // voxels: Gaussian blur of each grain's grey field before the iso-surface (0: none)
};

// Grey levels that place the surface between voxels with sub-voxel accuracy
// (the partial-volume grey level of a surface voxel says how much of it is
// solid). Absent for label images, whose surfaces lie halfway between voxels.
struct GreyField {
  const GreyVolume* grey = nullptr;
  float threshold = 0;        // the solid/pore threshold
  float pore_level = 0;       // mean grey level of the pores
  float solid_level = 0;      // mean grey level of the grains
};

struct GrainMesh {
  TriMesh mesh;                 // world coordinates (m), closed and outward
  int dropped_pieces = 0;       // separate surface pieces of the label left out (all but the largest)
  bool within_budget = true;    // simplify_mesh reached the face budget
};

// Meshes region `region` of `labels`. The field is the grey level where the
// voxel belongs to this grain (raised to just above the threshold where a
// filled pore made it solid) or to no grain (lowered to just below), and the
// pore level in other grains and outside the image, so a grain's surface
// stops halfway to a touching neighbour. Without grey levels, the
// indicator of the label at 1/2. Throws RunError if the mesh fails check_mesh.
GrainMesh mesh_grain(const LabelVolume& labels, const Region& region, const std::optional<GreyField>& grey,
                     const MeshingOptions& options);

}  // namespace grainlab::ct
