// The fixed part of a simulation (MuJoCo's mjModel): shapes, materials, body
// constants, walls, the contact law. Nothing here changes while a run steps.
//
// Every body's local frame is its principal frame: origin at the centre of
// mass, axes along the principal axes, so its inertia tensor is diagonal.
// A shape is shared by all bodies that use it; each body has its own uniform
// scale s, so mass = rho V s^3 and inertia = rho J s^5 (V, J of the shape at s = 1).
#pragma once

#include "collision/compound.h"
#include "collision/shape_kind.h"
#include "collision/shapes.h"
#include "core/types.h"
#include "dynamics/contact_law.h"
#include "dynamics/material.h"
#include "geometry/convex_decomposition.h"
#include "geometry/trimesh.h"

#include <memory>
#include <string>
#include <vector>

namespace grainlab {

// A grain shape. What every kind has is here; what a kind has of its own (a
// polytope's hull, a compound's pieces) is `geometry`, which only the kind's
// pair routines read (collision/shape_kind.h says each kind's type), so that a
// new kind adds no field here.
struct Shape {
  using Kind = ShapeKind;  // Sphere, Polytope, Compound or a registered kind (collision/shape_kind.h)
  Kind kind = Kind::Sphere;
  std::string name;
  bool isotropic = false;            // inertia is a multiple of the identity (spheres): free rotation is exact
  double volume = 0;                 // m^3 at scale 1
  Vec3 unit_moments = Vec3::Zero();  // principal moments per unit density at scale 1 (m^5)
  double equivalent_radius = 0;      // radius of the sphere of equal volume, scale 1 (m)
  double bounding_radius = 0;        // max distance of the surface from the centroid, scale 1 (m)
  TriMesh mesh;                      // the surface in the principal frame, drawn and fingerprinted
                                     // (a concave grain's exact mesh; its pieces only collide); none for spheres
  // The kind's collision geometry in the principal frame at scale 1 (a
  // Polytope's ConvexPolytope, a Compound's CompoundShape; null for a
  // Sphere), shared by the bodies of the shape and by copies of the Model.
  std::shared_ptr<const void> geometry;

  // The geometry as the kind's type T.
  template <class T>
  const T& geometry_as() const {
    return *static_cast<const T*>(geometry.get());
  }
};

// One piece of a compound shape as given to Model::add_compound_shape: a
// sphere (radius > 0, centred at `center`) or, with radius 0, the convex hull
// of a closed mesh; coordinates of the shape's own frame (m).
struct CompoundPart {
  double radius = 0;
  Vec3 center = Vec3::Zero();
  TriMesh mesh;
};

// Constants of one body, derived from its shape, material and scale.
struct BodyModel {
  Index shape = 0;
  Index material = 0;
  double scale = 1;
  double mass = 0, inv_mass = 0;  // inertial mass (kg), density scaling included
  double gravity_mass = 0;        // true mass (kg): weight = gravity_mass * g
  Vec3 inertia = Vec3::Zero();    // principal moments (kg m^2), density scaling included
  Vec3 inv_inertia = Vec3::Zero();
  double radius = 0;              // Hertz radius: volume-equivalent radius (m)
  double bounding_radius = 0;     // m
};

// A rigid wall. Planes are half-spaces (solid behind the normal, the local +z
// axis); boxes are solid oriented boxes. Their motion is prescribed.
struct WallModel {
  using Kind = ShapeKind;  // Plane or Box (collision/shape_kind.h)
  Kind kind = Kind::Plane;
  std::string name;
  Index material = 0;
  Vec3 half = Vec3::Zero();  // box half extents (m)
};

struct Model {
  ContactLaw law;             // a registered law (dynamics/laws/registry.h); default hertz-material
  Vec3 gravity{0, 0, -9.81};  // m/s^2
  double density_scale = 1;   // multiplies inertial mass and inertia, not weight
  std::vector<Material> materials;
  std::vector<Shape> shapes;
  std::vector<BodyModel> bodies;
  std::vector<WallModel> walls;

  // A shape of any kind, filled by its kind's own builder (the ones below,
  // or a registered kind's): refuses one whose volume, moments or radii are
  // not positive and finite.
  Index add_shape(Shape s);
  // Shapes. A mesh shape is moved to its principal frame; its hull is the
  // collision shape (exact for convex grains), its mesh gives mass properties.
  Index add_sphere_shape(double radius, std::string name = "sphere");
  Index add_mesh_shape(const TriMesh& mesh, std::string name);
  // A compound of disjoint convex parts (1 to kMaxCompoundPieces; volumes and
  // inertias add, so overlapping parts would count twice), moved to its
  // principal frame.
  Index add_compound_shape(const std::vector<CompoundPart>& parts, std::string name);
  // A concave grain: mass properties from the exact closed mesh, collision by
  // the convex hulls of the pieces of `dec` (decompose_convex of that mesh;
  // 1 to kMaxCompoundPieces), each owning the contacts in its cell, moved to
  // the principal frame.
  Index add_concave_shape(const TriMesh& mesh, const ConvexDecomposition& dec, std::string name);
  Index add_material(const Material& m);

  // Coefficients of a material pair (valid after finalize()).
  const PairCoefficients& pair(Index ma, Index mb) const {
    return pair_table_[static_cast<std::size_t>(ma) * materials.size() + mb];
  }
  // Validates materials and mixes the pair table; called by World.
  void finalize();

  // Constants of a body of this shape, material and scale.
  BodyModel make_body(Index shape, Index material, double scale) const;
  // Recomputes the body constants (after density_scale changes).
  void rescale_bodies();

 private:
  std::vector<PairCoefficients> pair_table_;
};

}  // namespace grainlab
