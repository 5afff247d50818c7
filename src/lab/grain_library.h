// Puts the grain shapes a run asks for into a Model.
#pragma once

#include "dynamics/model.h"
#include "geometry/convex_decomposition.h"
#include "grains/grain_set.h"
#include "lab/lab_spec.h"

#include <string>
#include <vector>

namespace grainlab {

// How a run's grain shapes are collided (for run.json and the log).
struct GrainRepresentation {
  int shapes = 0;             // shapes in the library
  int concave_shapes = 0;     // of them, collided as convex pieces
  int pieces = 0;             // pieces of those, in all
  double hull_excess = 0;     // mean over the concave shapes: V(hull) / V - 1 (what the hull would fill in)
  double pieces_excess = 0;   // mean over the concave shapes: V(pieces) / V - 1
};

// True if a grain of this convexity is collided as pieces under `representation`
// ("hull", "concave", or "auto": below kConcaveBelow).
bool collides_as_pieces(const std::string& representation, double convexity);

// The grain set of a spec: generated from the preset (with spec.convexity),
// or imported from the folder.
GrainSet make_grain_set(const GrainsSpec& spec, std::uint64_t seed);

// Adds one shape per mesh (scale 1, meshes in metres) to `model`: analytic
// spheres of equal volume if `spheres`; else the hull, or convex pieces
// where `representation` asks for them (decomposed in parallel on `threads`
// threads, core/parallel.h; 0 = all cores).
std::vector<Index> add_mesh_shapes(Model& model, const std::vector<TriMesh>& meshes,
                                   const std::vector<std::string>& names, bool spheres,
                                   const std::string& representation, int threads,
                                   GrainRepresentation* report = nullptr);

// Adds spec.shapes grain shapes (generated from the preset, or imported from
// the folder) at their physical size to `model`, and returns their indices.
// Glass beads become analytic spheres; concave grains (spec.representation)
// become convex pieces with the exact mesh's mass properties (decomposed on
// `threads` threads, as add_mesh_shapes).
std::vector<Index> add_grain_shapes(Model& model, const GrainsSpec& spec, std::uint64_t seed, int threads,
                                    GrainRepresentation* report = nullptr);

}  // namespace grainlab
