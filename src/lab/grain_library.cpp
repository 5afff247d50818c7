// Grain shapes for a run (see grain_library.h). Until the grains layer's
// generator lands, the presets use the ellipsoidal convex grain.
#include "lab/grain_library.h"

#include "core/error.h"
#include "core/rng.h"
#include "grains/convex_grain.h"

#include <cmath>

namespace grainlab {

std::vector<Index> add_grain_shapes(Model& model, const GrainsSpec& spec, std::uint64_t seed) {
  Rng rng(seed ^ 0x677261696e73ULL);
  std::vector<Index> shapes;
  for (int k = 0; k < spec.shapes; ++k) {
    const double d = rng.uniform(spec.d_min, spec.d_max);
    if (spec.preset == "glass-beads") {
      shapes.push_back(model.add_sphere_shape(0.5 * d, "bead" + std::to_string(k)));
      continue;
    }
    ConvexGrainSpec gs;
    gs.equivalent_radius = 0.5 * d;
    gs.points = spec.faces / 2 + 2;
    shapes.push_back(model.add_mesh_shape(convex_grain(gs, rng), "grain" + std::to_string(k)));
  }
  return shapes;
}

}  // namespace grainlab
