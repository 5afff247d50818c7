// Grain shapes for a run (see grain_library.h): the grains layer generates or
// imports them; glass beads become analytic spheres of the same volume;
// concave grains are collided as convex pieces (convex_decomposition.h)
// when grains.representation asks for it.
#include "lab/grain_library.h"

#include "core/parallel.h"
#include "geometry/convex_hull.h"
#include "geometry/decomposition_cache.h"
#include "geometry/mass_properties.h"
#include "grains/grain_set.h"
#include "grains/sh_sands.h"

#include <cmath>
#include <numbers>

namespace grainlab {

bool collides_as_pieces(const std::string& representation, double convexity) {
  if (representation == "concave") return true;
  if (representation == "hull") return false;
  return convexity < kConcaveBelow;  // "auto"
}

GrainSet make_grain_set(const GrainsSpec& spec, std::uint64_t seed) {
  const SieveRange sieve{spec.d_min, spec.d_max};
  if (!spec.folder.empty()) return import_grain_set(spec.folder, spec.faces, sieve);
  if (find_sh_sand(spec.preset)) return generate_sh_grain_set(spec.preset, spec.shapes, seed, sieve, spec.faces);
  GeneratorSpec g = preset_spec(parse_grain_preset(spec.preset));
  g.faces = spec.faces;
  g.convexity = spec.convexity;
  return generate_grain_set(g, spec.shapes, seed, sieve);
}

std::vector<Index> add_mesh_shapes(Model& model, const std::vector<TriMesh>& meshes,
                                   const std::vector<std::string>& names, bool spheres,
                                   const std::string& representation, int threads, GrainRepresentation* report) {
  const int n = static_cast<int>(meshes.size());
  // Decompose first (in parallel: a 2000-face grain takes about 2 s; a shape
  // this process has decomposed before is looked up), then add in order.
  std::vector<ConvexDecomposition> pieces(n);
  std::vector<char> concave(n, 0);
  if (!spheres) {
    parallel_for(
        n,
        [&](std::ptrdiff_t k) {
          concave[k] = collides_as_pieces(representation, convexity(meshes[k]));
          if (!concave[k]) return;
          DecompositionOptions o;
          o.max_pieces = kMaxCompoundPieces;
          pieces[k] = decompose_convex_cached(meshes[k], o);
          if (pieces[k].pieces.size() == 1) concave[k] = 0;  // convex after all: the hull path
        },
        1, threads);
  }
  GrainRepresentation r;
  std::vector<Index> shapes;
  for (int k = 0; k < n; ++k) {
    if (spheres) {
      const double volume = mass_properties(meshes[k]).volume;
      shapes.push_back(model.add_sphere_shape(std::cbrt(3 * volume / (4 * std::numbers::pi)), names[k]));
    } else if (concave[k]) {
      shapes.push_back(model.add_concave_shape(meshes[k], pieces[k], names[k]));
      ++r.concave_shapes;
      r.pieces += static_cast<int>(pieces[k].pieces.size());
      r.hull_excess += pieces[k].hull_excess();
      r.pieces_excess += pieces[k].excess();
    } else {
      shapes.push_back(model.add_mesh_shape(meshes[k], names[k]));
    }
  }
  if (r.concave_shapes > 0) {
    r.hull_excess /= r.concave_shapes;
    r.pieces_excess /= r.concave_shapes;
  }
  r.shapes = n;
  if (report) *report = r;
  return shapes;
}

std::vector<Index> add_grain_shapes(Model& model, const GrainsSpec& spec, std::uint64_t seed, int threads,
                                    GrainRepresentation* report) {
  const GrainSet set = make_grain_set(spec, seed);
  return add_mesh_shapes(model, set.meshes, set.names, set.spheres, spec.representation, threads, report);
}

}  // namespace grainlab
