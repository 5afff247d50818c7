// The iso-surface of a sampled scalar field, as a closed triangle mesh.
//
// Method (written from the definition): each grid cube is cut into the six
// tetrahedra of its Kuhn triangulation (the paths 000 -> e_a -> e_a + e_b -> 111
// over the orderings (a, b, c) of the axes). Every cube uses the same
// diagonal, so neighbouring cubes cut their shared face along the same face
// diagonal and the pieces meet without cracks. Inside a tetrahedron the field
// is taken linear, so its level set is a plane: one triangle when one corner
// is on its own side, a quadrilateral (two triangles) when two are. Vertices
// sit on the cut edges at t = (iso - f_a) / (f_b - f_a), kept 1e-3 away from
// the corners so no two vertices coincide, and are shared between the
// tetrahedra around an edge. The level set of a piecewise-linear field is a
// 2-manifold, so with the field below iso on the grid's outer layer the mesh
// is closed and manifold. Each triangle is wound so that its normal points
// from the corners above iso (inside) to those below.
//
// Compared with marching cubes' 256-case table, this needs no table and has no
// ambiguous faces, at the price of about twice the triangles (the caller
// simplifies to a face budget anyway).
#pragma once

#include "ct/volume.h"
#include "geometry/trimesh.h"

#include <vector>

namespace grainlab::ct {

// The surface {f = iso} around the region f > iso of a field of size
// nx x ny x nz (x fastest), in voxel-index coordinates (voxel (i, j, k) at
// (i, j, k)). The outer layer of the grid must be below iso.
TriMesh iso_surface(const std::vector<float>& field, const Size3& size, float iso);

// The vertex-connected pieces of a mesh (each closed piece of an iso-surface
// is one), largest enclosed volume first.
std::vector<TriMesh> mesh_components(const TriMesh& mesh);

}  // namespace grainlab::ct
