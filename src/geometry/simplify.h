// Mesh simplification to a face budget (meshoptimizer's edge collapse), with
// the result verified: closed, manifold, outward and of nearly the same volume.
#pragma once

#include "geometry/trimesh.h"

namespace grainlab {

// What simplify_mesh did.
struct SimplifyResult {
  TriMesh mesh;               // the simplified mesh (the input itself when it already fits)
  double volume_error = 0;    // |V_out - V_in| / V_in
  int target_faces = 0;       // the budget that produced `mesh` (>= the requested one after retries)
  bool within_budget = true;  // false: no simplification within the budget kept the checks
};

// Reduces a closed, outward mesh to at most `face_budget` faces, keeping it
// closed (check_mesh ok) and its volume within `max_volume_error` (relative).
// When the budget cannot keep both, retries with budgets 25 % larger each time;
// if even those fail, returns the input unchanged with within_budget = false.
// Vertices keep their double-precision positions (meshoptimizer only chooses
// which to keep). Throws InputError for face_budget < 4.
SimplifyResult simplify_mesh(const TriMesh& mesh, int face_budget, double max_volume_error = 0.01);

}  // namespace grainlab
