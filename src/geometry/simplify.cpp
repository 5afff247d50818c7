// Simplification through meshoptimizer (see simplify.h).
//
// meshopt_simplify (0.18) collapses edges by quadric error while refusing
// collapses that would change the topology, so a closed manifold stays closed
// in practice; it stops at the target index count or when the deformation
// would exceed target_error (relative to the mesh extent). Neither the volume
// nor closedness is guaranteed, so both are checked after every attempt.
#include "geometry/simplify.h"

#include "core/error.h"
#include "geometry/mass_properties.h"
#include "geometry/mesh_check.h"

#include <meshoptimizer.h>

#include <cmath>

namespace grainlab {
namespace {

// The faces that meshoptimizer kept, with vertices renumbered in order of first use.
TriMesh compact(const TriMesh& mesh, const std::vector<unsigned>& indices, std::size_t count) {
  TriMesh out;
  std::vector<Index> remap(mesh.vertices.size(), -1);
  for (std::size_t i = 0; i + 2 < count; i += 3) {
    Face f;
    for (int k = 0; k < 3; ++k) {
      const unsigned v = indices[i + k];
      if (remap[v] < 0) {
        remap[v] = static_cast<Index>(out.vertices.size());
        out.vertices.push_back(mesh.vertices[v]);
      }
      f[k] = remap[v];
    }
    out.faces.push_back(f);
  }
  return out;
}

}  // namespace

SimplifyResult simplify_mesh(const TriMesh& mesh, int face_budget, double max_volume_error) {
  if (face_budget < 4) input_error("simplify: the face budget must be at least 4, got {}", face_budget);
  SimplifyResult result;
  result.mesh = mesh;
  result.target_faces = face_budget;
  const int faces = static_cast<int>(mesh.faces.size());
  if (faces <= face_budget) return result;

  const double v0 = mass_properties(mesh).volume;
  std::vector<float> positions;
  positions.reserve(mesh.vertices.size() * 3);
  for (const Vec3& v : mesh.vertices) {
    positions.insert(positions.end(), {static_cast<float>(v.x()), static_cast<float>(v.y()),
                                       static_cast<float>(v.z())});
  }
  std::vector<unsigned> indices;
  indices.reserve(mesh.faces.size() * 3);
  for (const Face& f : mesh.faces) {
    for (Index v : f) indices.push_back(static_cast<unsigned>(v));
  }
  std::vector<unsigned> out(indices.size());
  // Deformation allowed per attempt: generous, since the count is the goal and
  // the volume check below is the acceptance test.
  constexpr float kTargetError = 0.05f;
  for (int target = face_budget; target < faces; target = static_cast<int>(std::ceil(target * 1.25))) {
    const std::size_t n = meshopt_simplify(out.data(), indices.data(), indices.size(), positions.data(),
                                           mesh.vertices.size(), 3 * sizeof(float),
                                           static_cast<std::size_t>(target) * 3, kTargetError, 0, nullptr);
    TriMesh candidate = compact(mesh, out, n);
    if (candidate.faces.size() < 4 || !check_mesh(candidate).ok()) continue;
    const double v = mass_properties(candidate).volume;
    const double err = std::abs(v - v0) / v0;
    if (err > max_volume_error) continue;
    result.mesh = std::move(candidate);
    result.volume_error = err;
    result.target_faces = target;
    result.within_budget = static_cast<int>(result.mesh.faces.size()) <= face_budget;
    return result;
  }
  result.within_budget = false;
  return result;
}

}  // namespace grainlab
