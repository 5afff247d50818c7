// Grain shapes for a run (see grain_library.h): the grains layer generates or
// imports them; glass beads become analytic spheres of the same volume.
#include "lab/grain_library.h"

#include "geometry/mass_properties.h"
#include "grains/grain_set.h"

#include <cmath>
#include <numbers>

namespace grainlab {

std::vector<Index> add_grain_shapes(Model& model, const GrainsSpec& spec, std::uint64_t seed) {
  const SieveRange sieve{spec.d_min, spec.d_max};
  const GrainSet set = spec.folder.empty()
                           ? generate_grain_set(parse_grain_preset(spec.preset), spec.shapes, seed, sieve, spec.faces)
                           : import_grain_set(spec.folder, spec.faces, sieve);
  std::vector<Index> shapes;
  for (std::size_t k = 0; k < set.meshes.size(); ++k) {
    if (set.spheres) {
      const double volume = mass_properties(set.meshes[k]).volume;
      shapes.push_back(model.add_sphere_shape(std::cbrt(3 * volume / (4 * std::numbers::pi)), set.names[k]));
    } else {
      shapes.push_back(model.add_mesh_shape(set.meshes[k], set.names[k]));
    }
  }
  return shapes;
}

}  // namespace grainlab
