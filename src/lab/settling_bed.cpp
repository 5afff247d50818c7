// The settling-bed scene (see settling_bed.h).
#include "lab/settling_bed.h"

#include "core/rng.h"
#include "grains/convex_grain.h"

#include <cmath>

namespace grainlab {

SettlingBedSpec frictionless_faceted_bed_spec() {
  SettlingBedSpec spec;
  spec.grains = 300;
  spec.hull_points = 22;  // 40-face hulls
  spec.seed = 5;
  spec.spacing = 1.02;
  spec.material.youngs_modulus = 1e7;
  spec.material.restitution = 0.3;
  spec.material.friction = 0;
  return spec;
}

SettlingBed make_settling_bed(const SettlingBedSpec& spec) {
  SettlingBed bed;
  World& w = bed.world;
  w.model.law = spec.law;
  const Index mat = w.model.add_material(spec.material);
  Rng rng(spec.seed);

  std::vector<Index> shapes;
  if (spec.spheres) {
    shapes.push_back(w.model.add_sphere_shape(1.0, "bead"));
  } else {
    ConvexGrainSpec gs;
    gs.equivalent_radius = 1.0;
    gs.points = spec.hull_points;
    for (int k = 0; k < spec.shape_count; ++k)
      shapes.push_back(w.model.add_mesh_shape(convex_grain(gs, rng), "grain" + std::to_string(k)));
  }
  double max_bound = 0;
  for (Index s : shapes) max_bound = std::max(max_bound, w.model.shapes[s].bounding_radius);
  bed.max_radius = max_bound * spec.radius * 1.1;

  const double pitch = 2.0 * bed.max_radius * spec.spacing;
  const int cols = spec.columns > 0 ? spec.columns
                                    : std::max(2, static_cast<int>(std::ceil(1.3 * std::cbrt(spec.grains))));
  bed.box_half_width = 0.5 * cols * pitch;
  for (int i = 0; i < spec.grains; ++i) {
    const int layer = i / (cols * cols), in_layer = i % (cols * cols);
    const Vec3 x((in_layer % cols + 0.5) * pitch - bed.box_half_width,
                 (in_layer / cols + 0.5) * pitch - bed.box_half_width, (layer + 0.5) * pitch);
    const Index shape = shapes[rng.next_u64() % shapes.size()];
    const double scale = spec.radius * rng.uniform(0.9, 1.1);
    const Vec3 v = 0.05 * std::sqrt(9.81 * spec.radius) * rng.unit_vector();
    w.add_body(shape, mat, scale, x, rng.rotation(), v);
  }
  w.add_plane(Vec3::Zero(), Vec3::UnitZ(), mat, "floor");
  const double h = bed.box_half_width;
  w.add_plane(Vec3(-h, 0, 0), Vec3::UnitX(), mat, "wall-x");
  w.add_plane(Vec3(h, 0, 0), -Vec3::UnitX(), mat, "wall+x");
  w.add_plane(Vec3(0, -h, 0), Vec3::UnitY(), mat, "wall-y");
  w.add_plane(Vec3(0, h, 0), -Vec3::UnitY(), mat, "wall+y");
  return bed;
}

bool all_grains_inside(const SettlingBed& bed) {
  for (const BodyState& b : bed.world.state.bodies) {
    if (!b.x.allFinite() || b.x.z() < 0 || std::abs(b.x.x()) > bed.box_half_width ||
        std::abs(b.x.y()) > bed.box_half_width)
      return false;
  }
  return true;
}

double max_relative_overlap(const World& world) {
  double worst = 0;
  for (const Contact& pc : world.state.contacts) {
    if (!pc.geo.touching) continue;
    const double r = std::min(world.model.bodies[pc.a].radius, world.model.bodies[pc.b].radius);
    worst = std::max(worst, pc.geo.depth / r);
  }
  for (const Contact& pc : world.state.wall_contacts) {
    if (pc.geo.touching) worst = std::max(worst, pc.geo.depth / world.model.bodies[pc.b].radius);
  }
  return worst;
}

}  // namespace grainlab
