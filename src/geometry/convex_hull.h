// Convex hull (qhull) with the vertex adjacency that support queries climb.
#pragma once

#include "geometry/trimesh.h"

#include <span>

namespace grainlab {

// A convex polytope: triangulated surface plus the edge graph for hill climbing.
struct ConvexHull {
  std::vector<Vec3> vertices;   // hull vertices only, in input order
  std::vector<Index> input_index;  // per hull vertex: its index in the input points
  std::vector<Face> faces;      // triangulated, outward (counter-clockwise from outside)
  // Vertex adjacency in compressed rows: neighbours of v are
  // adjacency[adjacency_offsets[v] .. adjacency_offsets[v+1]).
  std::vector<Index> adjacency_offsets;
  std::vector<Index> adjacency;

  // The hull as a closed triangle mesh.
  TriMesh mesh() const { return {vertices, faces}; }
};

// Hull of a point set. Throws InputError if the points are fewer than 4,
// non-finite, or (nearly) coplanar.
ConvexHull convex_hull(std::span<const Vec3> points);

// Volume of a closed mesh over the volume of its convex hull (1 for a convex mesh).
double convexity(const TriMesh& mesh);

// True if no vertex lies farther than tol * (bounding-box diagonal) outside the
// plane of any non-degenerate face: the mesh is (within tol) its own hull.
bool is_convex(const TriMesh& mesh, double tol);

}  // namespace grainlab
