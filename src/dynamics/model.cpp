// Shape and body constants (see model.h for the conventions).
#include "dynamics/model.h"

#include "core/error.h"
#include "geometry/convex_hull.h"
#include "geometry/mass_properties.h"
#include "geometry/primitives.h"

#include <Eigen/Eigenvalues>

#include <cmath>
#include <numbers>
#include <span>

namespace grainlab {

Index Model::add_shape(Shape s) {
  const auto positive = [](double v) { return v > 0 && std::isfinite(v); };
  if (!positive(s.volume) || !positive(s.equivalent_radius) || !positive(s.bounding_radius) ||
      !positive(s.unit_moments.minCoeff()) || !std::isfinite(s.unit_moments.maxCoeff()))
    input_error("shape '{}': volume {} m^3, principal moments ({}, {}, {}) m^5, equivalent radius {} m and "
                "bounding radius {} m must all be positive and finite",
                s.name, s.volume, s.unit_moments.x(), s.unit_moments.y(), s.unit_moments.z(), s.equivalent_radius,
                s.bounding_radius);
  shapes.push_back(std::move(s));
  return static_cast<Index>(shapes.size() - 1);
}

Index Model::add_sphere_shape(double radius, std::string name) {
  if (!(radius > 0 && std::isfinite(radius)))
    input_error("sphere shape '{}': radius {} m must be positive and finite", name, radius);
  Shape s;
  s.kind = Shape::Kind::Sphere;
  s.isotropic = true;
  s.name = std::move(name);
  s.volume = 4.0 / 3.0 * std::numbers::pi * radius * radius * radius;
  // Solid sphere: I = (2/5) m r^2 = (2/5) rho V r^2.
  s.unit_moments = Vec3::Constant(0.4 * s.volume * radius * radius);
  s.equivalent_radius = radius;
  s.bounding_radius = radius;
  return add_shape(std::move(s));
}

namespace {

// A mesh shape's exact mass properties, and its mesh moved into the principal frame.
Shape principal_mesh_shape(const TriMesh& mesh, const MassProperties& mp, std::string name) {
  Shape s;
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
  return s;
}

ConvexPolytope polytope_of(std::span<const Vec3> points) {
  const ConvexHull hull = convex_hull(points);
  return ConvexPolytope(hull.vertices, hull.adjacency_offsets, hull.adjacency);
}

}  // namespace

Index Model::add_mesh_shape(const TriMesh& mesh, std::string name) {
  const MassProperties mp = mass_properties(mesh);
  if (!(mp.volume > 0)) input_error("shape '{}': the mesh has no volume", name);
  Shape s = principal_mesh_shape(mesh, mp, std::move(name));
  s.kind = Shape::Kind::Polytope;
  s.geometry = std::make_shared<const ConvexPolytope>(polytope_of(s.mesh.vertices));
  return add_shape(std::move(s));
}

Index Model::add_concave_shape(const TriMesh& mesh, const ConvexDecomposition& dec, std::string name) {
  const auto& pieces = dec.pieces;
  if (pieces.empty() || pieces.size() > static_cast<std::size_t>(kMaxCompoundPieces))
    input_error("concave shape '{}': {} pieces; give 1 to {}", name, pieces.size(), kMaxCompoundPieces);
  const MassProperties mp = mass_properties(mesh);
  if (!(mp.volume > 0)) input_error("shape '{}': the mesh has no volume", name);
  Shape s = principal_mesh_shape(mesh, mp, std::move(name));
  s.kind = Shape::Kind::Compound;
  CompoundShape compound;
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    const std::vector<Vec3>& points = pieces[k];
    // The piece's points in the principal frame, about their mean (the piece's offset).
    std::vector<Vec3> local;
    Vec3 mean = Vec3::Zero();
    for (const Vec3& p : points) {
      local.push_back(mp.principal_axes.transpose() * (p - mp.centroid));
      mean += local.back();
    }
    mean /= static_cast<double>(local.size());
    for (Vec3& p : local) {
      p -= mean;
      s.bounding_radius = std::max(s.bounding_radius, (p + mean).norm());
    }
    CompoundPiece piece;
    piece.kind = Shape::Kind::Polytope;
    piece.offset = mean;
    piece.hull = polytope_of(local);
    // The cell n.p <= c in the principal frame: p = A p' + C, so (A^T n).p' <= c - n.C.
    if (k < dec.cells.size())
      for (const HalfSpace& h : dec.cells[k])
        piece.cell.push_back({mp.principal_axes.transpose() * h.n, h.c - h.n.dot(mp.centroid)});
    compound.pieces.push_back(std::move(piece));
  }
  s.geometry = std::make_shared<const CompoundShape>(std::move(compound));
  return add_shape(std::move(s));
}

// Mass properties of a compound: volumes add; the centroid is the
// volume-weighted mean C = sum V_k c_k / V; the inertia about C (per unit
// density) is sum J_k + V_k (|d_k|^2 I - d_k d_k^T), d_k = c_k - C (parallel
// axes), J_k the part's own inertia about c_k (sphere: (2/5) V r^2 I). Its
// eigenvectors A (right-handed) give the principal frame: p' = A^T (p - C).
Index Model::add_compound_shape(const std::vector<CompoundPart>& parts, std::string name) {
  if (parts.empty() || parts.size() > static_cast<std::size_t>(kMaxCompoundPieces))
    input_error("compound shape '{}': {} parts; give 1 to {}", name, parts.size(), kMaxCompoundPieces);
  std::vector<double> vol(parts.size());
  std::vector<Vec3> cen(parts.size());
  std::vector<Mat3> own(parts.size());
  double volume = 0;
  Vec3 c = Vec3::Zero();
  for (std::size_t k = 0; k < parts.size(); ++k) {
    const CompoundPart& p = parts[k];
    if (p.radius > 0) {
      vol[k] = 4.0 / 3.0 * std::numbers::pi * p.radius * p.radius * p.radius;
      cen[k] = p.center;
      own[k] = (0.4 * vol[k] * p.radius * p.radius) * Mat3::Identity();
    } else {
      const MassProperties mp = mass_properties(p.mesh);
      if (!(mp.volume > 0)) input_error("compound shape '{}': part {} has no volume", name, k);
      vol[k] = mp.volume;
      cen[k] = mp.centroid;
      own[k] = mp.inertia;
    }
    volume += vol[k];
    c += vol[k] * cen[k];
  }
  c /= volume;
  Mat3 inertia = Mat3::Zero();
  for (std::size_t k = 0; k < parts.size(); ++k) {
    const Vec3 d = cen[k] - c;
    inertia += own[k] + vol[k] * (d.squaredNorm() * Mat3::Identity() - d * d.transpose());
  }
  const Eigen::SelfAdjointEigenSolver<Mat3> eig(inertia);
  Mat3 axes = eig.eigenvectors();
  if (axes.determinant() < 0) axes.col(2) = -axes.col(2);
  Shape s;
  s.kind = Shape::Kind::Compound;
  s.name = std::move(name);
  s.volume = volume;
  s.unit_moments = eig.eigenvalues();
  s.equivalent_radius = std::cbrt(3.0 * volume / (4.0 * std::numbers::pi));
  CompoundShape compound;
  for (std::size_t k = 0; k < parts.size(); ++k) {
    const CompoundPart& p = parts[k];
    CompoundPiece piece;
    piece.offset = axes.transpose() * (cen[k] - c);
    TriMesh local = p.radius > 0 ? icosphere(p.radius, 2) : p.mesh;  // about the part's centre
    if (p.radius > 0) {
      piece.kind = Shape::Kind::Sphere;
      piece.radius = p.radius;
    } else {
      for (Vec3& v : local.vertices) v = axes.transpose() * (v - cen[k]);
      piece.kind = Shape::Kind::Polytope;
      piece.hull = polytope_of(local.vertices);
    }
    // The drawn surface: every part's mesh in the principal frame.
    const Index base = static_cast<Index>(s.mesh.vertices.size());
    for (const Vec3& v : local.vertices) {
      s.mesh.vertices.push_back(piece.offset + v);
      s.bounding_radius = std::max(s.bounding_radius, s.mesh.vertices.back().norm());
    }
    if (p.radius > 0) s.bounding_radius = std::max(s.bounding_radius, piece.offset.norm() + p.radius);
    for (const auto& f : local.faces) s.mesh.faces.push_back({f[0] + base, f[1] + base, f[2] + base});
    compound.pieces.push_back(std::move(piece));
  }
  s.geometry = std::make_shared<const CompoundShape>(std::move(compound));
  return add_shape(std::move(s));
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
