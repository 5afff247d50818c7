// Specimen placement and deposition (rules in specimen.h).
#include "lab/specimen.h"

#include "core/error.h"
#include "core/rng.h"
#include "lab/grain_library.h"
#include "lab/specimen_budget.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace grainlab {

Specimen place_loose_specimen(World& world, const LabSpec& spec, Index grain_material) {
  Model& m = world.model;
  Specimen sp;
  const std::vector<Index> shapes = add_grain_shapes(m, spec.grains, spec.seed, spec.numerics.threads, &sp.representation);
  double mean_volume = 0, max_bound = 0;
  for (Index s : shapes) {
    mean_volume += m.shapes[s].volume / shapes.size();
    max_bound = std::max(max_bound, m.shapes[s].bounding_radius);
  }
  sp.mean_diameter = std::cbrt(6.0 * mean_volume / std::numbers::pi);

  const double L = spec.box.length, W = spec.box.width;
  const double e_target = spec.target_void_ratio();
  const double wanted = specimen_grain_count(spec.box, e_target, mean_volume);
  refuse_impossible_specimen(wanted, available_memory_bytes(), spec.box, sp.mean_diameter,
                             "the specimen (box.length x box.width x box.height)");
  const int count = static_cast<int>(std::lround(wanted));
  const double pitch = 2.0 * max_bound * 1.05;
  const int nx = static_cast<int>(L / pitch), ny = static_cast<int>(W / pitch);
  if (nx < 1 || ny < 1)
    input_error("box {} x {} mm is smaller than one grain ({:.3f} mm across): make the box larger "
                "or the grains smaller",
                L * 1e3, W * 1e3, pitch * 1e3);
  Rng rng(spec.seed);
  const double sx = L / nx, sy = W / ny;
  for (int i = 0; i < count; ++i) {
    const int layer = i / (nx * ny), in_layer = i % (nx * ny);
    const Vec3 x(-0.5 * L + (in_layer % nx + 0.5) * sx, -0.5 * W + (in_layer / nx + 0.5) * sy,
                 (layer + 0.5) * pitch);
    const Index shape = shapes[rng.next_u64() % shapes.size()];
    // One draw a statement: the order of a call's arguments is the compiler's
    // choice, and a seed must give the same specimen whatever compiled it.
    const Vec3 v = 1e-3 * rng.unit_vector();
    const Quat q = rng.rotation();
    world.add_body(shape, grain_material, 1.0, x, q, v);
    sp.solid_volume += m.shapes[shape].volume;
    sp.mean_mass += m.bodies.back().gravity_mass / count;
  }
  sp.fill_top = (count / (nx * ny) + 1) * pitch + pitch;
  return sp;
}

PhaseOverrides deposition_overrides(const World& w, const LabSpec& spec, Index grain_material) {
  PhaseOverrides o = compaction_overrides(spec, grain_material);
  o.gravity = Vec3(0, 0, -kDepositionGravity * kStandardGravity * w.model.density_scale);
  return o;
}

PhaseOverrides compaction_overrides(const LabSpec& spec, Index grain_material) {
  PhaseOverrides o;
  o.friction.emplace_back(grain_material, spec.specimen.deposition_friction);
  return o;
}

bool deposit_settled(const World& w, const Specimen& s) {
  const double lift = s.mean_mass * w.model.density_scale * kDepositionGravity * kStandardGravity * s.mean_diameter;
  return w.kinetic_energy() < 1e-3 * lift * w.model.bodies.size();
}

void lower_cap_onto_grains(World& w, Index cap, double mean_diameter) {
  double top = 0;
  for (std::size_t i = 0; i < w.model.bodies.size(); ++i)
    top = std::max(top, w.state.bodies[i].x.z() + w.model.bodies[i].bounding_radius);
  w.state.walls[cap].x.z() = top + 0.05 * mean_diameter;
}

}  // namespace grainlab
