// Shape and body constants (see model.h for the conventions).
#include "dynamics/model.h"

#include "core/error.h"
#include "geometry/convex_hull.h"
#include "geometry/mass_properties.h"

#include <cmath>
#include <numbers>

namespace grainlab {

Index Model::add_sphere_shape(double radius, std::string name) {
  if (!(radius > 0 && std::isfinite(radius)))
    input_error("sphere shape '{}': radius {} m must be positive and finite", name, radius);
  Shape s;
  s.kind = Shape::Kind::Sphere;
  s.name = std::move(name);
  s.volume = 4.0 / 3.0 * std::numbers::pi * radius * radius * radius;
  // Solid sphere: I = (2/5) m r^2 = (2/5) rho V r^2.
  s.unit_moments = Vec3::Constant(0.4 * s.volume * radius * radius);
  s.equivalent_radius = radius;
  s.bounding_radius = radius;
  shapes.push_back(std::move(s));
  return static_cast<Index>(shapes.size() - 1);
}

Index Model::add_mesh_shape(const TriMesh& mesh, std::string name) {
  const MassProperties mp = mass_properties(mesh);
  if (!(mp.volume > 0)) input_error("shape '{}': the mesh has no volume", name);
  Shape s;
  s.kind = Shape::Kind::Polytope;
  s.name = std::move(name);
  s.volume = mp.volume;
  s.unit_moments = mp.principal_moments;
  s.equivalent_radius = std::cbrt(3.0 * mp.volume / (4.0 * std::numbers::pi));
  // Into the principal frame: p_local = A^T (p - c).
  s.mesh.faces = mesh.faces;
  s.mesh.vertices.reserve(mesh.vertices.size());
  for (const Vec3& p : mesh.vertices) {
    s.mesh.vertices.push_back(mp.principal_axes.transpose() * (p - mp.centroid));
    s.bounding_radius = std::max(s.bounding_radius, s.mesh.vertices.back().norm());
  }
  const ConvexHull hull = convex_hull(s.mesh.vertices);
  s.hull = ConvexPolytope(hull.vertices, hull.adjacency_offsets, hull.adjacency);
  shapes.push_back(std::move(s));
  return static_cast<Index>(shapes.size() - 1);
}

Index Model::add_material(const Material& m) {
  validate(m, law);
  materials.push_back(m);
  return static_cast<Index>(materials.size() - 1);
}

void Model::finalize() {
  if (materials.empty()) materials.push_back(Material{});
  const std::size_t n = materials.size();
  pair_table_.assign(n * n, {});
  for (std::size_t a = 0; a < n; ++a) {
    validate(materials[a], law);
    for (std::size_t b = 0; b < n; ++b) pair_table_[a * n + b] = mix(materials[a], materials[b], law);
  }
  if (!(density_scale > 0 && std::isfinite(density_scale)))
    input_error("density scaling factor {} must be positive and finite", density_scale);
}

BodyModel Model::make_body(Index shape, Index material, double scale) const {
  if (shape < 0 || static_cast<std::size_t>(shape) >= shapes.size())
    input_error("body refers to shape {} but the model has {} shapes", shape, shapes.size());
  if (material < 0 || static_cast<std::size_t>(material) >= materials.size())
    input_error("body refers to material {} but the model has {} materials", material, materials.size());
  if (!(scale > 0 && std::isfinite(scale))) input_error("body scale {} must be positive", scale);
  const Shape& s = shapes[shape];
  const double rho = materials[material].density;
  BodyModel b;
  b.shape = shape;
  b.material = material;
  b.scale = scale;
  const double s3 = scale * scale * scale, s5 = s3 * scale * scale;
  b.gravity_mass = rho * s.volume * s3;
  b.mass = b.gravity_mass * density_scale;
  b.inv_mass = 1.0 / b.mass;
  b.inertia = rho * density_scale * s5 * s.unit_moments;
  b.inv_inertia = b.inertia.cwiseInverse();
  b.radius = s.equivalent_radius * scale;
  b.bounding_radius = s.bounding_radius * scale;
  return b;
}

void Model::rescale_bodies() {
  for (BodyModel& b : bodies) b = make_body(b.shape, b.material, b.scale);
}

}  // namespace grainlab
