// Mesh defects: find them, repair the safe ones, refuse the rest.
#pragma once

#include "geometry/trimesh.h"

#include <filesystem>
#include <string>
#include <vector>

namespace grainlab {

// Counts of each defect found in a mesh. All zero (and not inside out) means a
// closed, manifold, consistently outward solid.
struct MeshCheck {
  Index vertices = 0;              // vertex count
  Index faces = 0;                 // face count
  Index bad_indices = 0;           // faces with a vertex index out of range
  Index non_finite_vertices = 0;   // vertices with a NaN or infinite coordinate
  Index degenerate_faces = 0;      // faces of zero area (repeated index included)
  Index repeated_index_faces = 0;  // faces naming one vertex twice (safe to drop)
  Index open_edges = 0;            // edges with one face: holes in the surface
  Index non_manifold_edges = 0;    // edges shared by more than two faces
  Index inconsistent_edges = 0;    // edges whose two faces wind the same way
  Index duplicate_vertices = 0;    // vertices within the merge tolerance of an earlier one
  Index unused_vertices = 0;       // vertices no face uses
  Index components = 0;            // edge-connected face components (information)
  double signed_volume = 0;        // sum over faces; meaningful when closed and consistent
  bool inside_out = false;         // closed and consistent, but signed volume < 0

  // True when nothing is wrong except zero-area faces with distinct vertices,
  // which are harmless to mass properties and collision.
  bool ok() const;
  // One line listing each defect with its count, or "closed, manifold, outward".
  std::string describe() const;
};

// Relative tolerance for merging vertices: a fraction of the bounding-box diagonal.
inline constexpr double kMergeTolerance = 1e-9;

// Finds every defect in `mesh`; never throws.
MeshCheck check_mesh(const TriMesh& mesh);

// Merges duplicate vertices (within kMergeTolerance of the bounding-box diagonal),
// drops unused vertices and faces with a repeated vertex, makes the winding
// consistent and outward (positive volume per connected component). Throws
// InputError naming `name` for what it cannot repair: empty, out-of-range
// indices, non-finite, open, non-manifold, non-orientable, zero volume.
// Every closed component is made outward on its own, so the inner wall of a
// hollow shell would be flipped too: grains are taken to be solid.
// A component wound inward (negative signed volume: normals pointing in, as
// some exporters write them) is turned outward, not refused: closed and
// consistent, its inside is unambiguous, and every measure and the collision
// need the outward one. When `notes` is given, each such repair adds a line
// there for the user (what was found, that it was turned).
TriMesh repair_mesh(const TriMesh& mesh, const std::string& name, std::vector<std::string>* notes = nullptr);

// Reads, repairs and checks a user's mesh file: the one way such files enter
// grainlab. `notes` as for repair_mesh.
TriMesh load_mesh(const std::filesystem::path& path, std::vector<std::string>* notes = nullptr);

}  // namespace grainlab
