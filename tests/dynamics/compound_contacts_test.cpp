// Sub-contacts below the body pair: a dumbbell (a compound of two spheres of
// radius r at +-L on a massless rod) touches a floor plane, or a slab grain,
// at both ends at once: two contacts of one body pair, each with its own
// tangential spring.
//
// Both bodies are held at fixed poses (re-set before every step) and the
// dumbbell is given velocity u along x with no spin, so at each contact the
// relative tangential velocity is u x_hat and the normal is z: the spring
// accumulates xi = n u dt after n steps (contact_law.h: xi += v_t dt, turned
// into the tangent plane, which here does not change). Friction is high, so
// the Coulomb cap never applies. A contact that stops touching forgets its
// spring; the other keeps its history.
#include "dynamics/world.h"
#include "geometry/mass_properties.h"
#include "geometry/primitives.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace grainlab;

namespace {

constexpr double r = 1e-3, L = 2e-3, d = 1e-6, u = 1e-3;

struct Pose {
  Vec3 x;
  Quat q;
};

struct Scene {
  World w;
  Index dumbbell = 0;
};

Index add_dumbbell_shape(Model& m) {
  CompoundPart left, right;
  left.radius = right.radius = r;
  left.center = Vec3(-L, 0, 0);
  right.center = Vec3(L, 0, 0);
  return m.add_compound_shape({left, right}, "dumbbell");
}

Material sticky() {
  Material m;
  m.youngs_modulus = 1e7;
  m.friction = 1e3;  // the Coulomb cap never bites
  return m;
}

// World centre of piece k of body i.
Vec3 piece_center(const World& w, Index i, int k) {
  const Shape& s = w.model.shapes[w.model.bodies[i].shape];
  return w.state.bodies[i].x + w.state.bodies[i].q * s.geometry_as<CompoundShape>().pieces[k].offset;
}

// Steps n times with every body held at its pose; the dumbbell moves at u x_hat.
void hold_and_step(World& w, const std::vector<Pose>& poses, Index moving, int n, double dt) {
  for (int k = 0; k < n; ++k) {
    for (std::size_t i = 0; i < poses.size(); ++i) {
      BodyState& b = w.state.bodies[i];
      b.x = poses[i].x;
      b.q = poses[i].q;
      b.v = static_cast<Index>(i) == moving ? Vec3(u, 0, 0) : Vec3::Zero();
      b.w = Vec3::Zero();
    }
    w.step(dt);
  }
}

// The contact of sub-contact `sub` in a list, or nullptr.
const Contact* find_sub(const std::vector<Contact>& list, int sub) {
  for (const Contact& c : list)
    if (c.sub == sub) return &c;
  return nullptr;
}

// Lifts piece `lifted` of the dumbbell by tilting the body from `pose` about
// the other piece's centre (about y), so that piece keeps its depth.
Pose tilted(World& w, Index i, const Pose& pose, int kept, int lifted) {
  w.state.bodies[i].x = pose.x;
  w.state.bodies[i].q = pose.q;
  const Vec3 c_kept = piece_center(w, i, kept);
  const double side = (piece_center(w, i, lifted) - c_kept).x() > 0 ? 1.0 : -1.0;
  const Quat tilt(Eigen::AngleAxisd(-0.05 * side, Vec3::UnitY()));
  return {c_kept + tilt * (w.state.bodies[i].x - c_kept), (tilt * w.state.bodies[i].q).normalized()};
}

}  // namespace

TEST(CompoundShape, DumbbellMassPropertiesByParallelAxes) {
  Model m;
  const Shape& s = m.shapes[add_dumbbell_shape(m)];
  const double v = 4.0 / 3.0 * std::numbers::pi * r * r * r;
  EXPECT_NEAR(s.volume, 2 * v, 1e-12 * v);
  // About the rod: 2 (2/5) v r^2; across it: 2 ((2/5) v r^2 + v L^2).
  EXPECT_NEAR(s.unit_moments[0], 0.8 * v * r * r, 1e-9 * v * r * r);
  EXPECT_NEAR(s.unit_moments[1], 0.8 * v * r * r + 2 * v * L * L, 1e-9 * v * L * L);
  EXPECT_NEAR(s.unit_moments[2], 0.8 * v * r * r + 2 * v * L * L, 1e-9 * v * L * L);
  ASSERT_EQ(s.geometry_as<CompoundShape>().pieces.size(), 2u);
  EXPECT_NEAR(s.geometry_as<CompoundShape>().pieces[0].offset.norm(), L, 1e-12);
  EXPECT_NEAR((s.geometry_as<CompoundShape>().pieces[0].offset + s.geometry_as<CompoundShape>().pieces[1].offset).norm(), 0, 1e-12);
  EXPECT_NEAR(s.bounding_radius, L + r, 1e-12);
  EXPECT_FALSE(s.isotropic);
}

TEST(CompoundShape, TwoSpringsOnAFloorEachWithItsOwnHistory) {
  World w;
  w.model.gravity = Vec3::Zero();
  const Index mat = w.model.add_material(sticky());
  const Index dumbbell = w.add_body(add_dumbbell_shape(w.model), mat, 1.0, Vec3(0, 0, r - d));
  w.add_plane(Vec3::Zero(), Vec3::UnitZ(), mat, "floor");
  const double dt = 0.1 * w.critical_time_step();
  const std::vector<Pose> flat{{w.state.bodies[dumbbell].x, w.state.bodies[dumbbell].q}};

  const int n1 = 40;
  hold_and_step(w, flat, dumbbell, n1, dt);
  ASSERT_EQ(w.state.wall_contacts.size(), 2u);
  EXPECT_EQ(w.contact_count(), 2u);
  EXPECT_EQ(w.touching_pair_count(), 1u);  // one body pair, two places
  for (int sub : {0, 1}) {
    const Contact* c = find_sub(w.state.wall_contacts, sub);
    ASSERT_NE(c, nullptr) << "sub-contact " << sub;
    EXPECT_NEAR(c->geo.depth, d, 1e-12);
    EXPECT_NEAR(c->xi.x(), n1 * u * dt, 1e-9 * n1 * u * dt);
    EXPECT_NEAR(c->xi.y(), 0, 1e-20);
    EXPECT_NEAR(c->xi.z(), 0, 1e-20);
  }

  // Lift the end of piece 1: its spring goes, piece 0's keeps accumulating.
  const std::vector<Pose> lifted{tilted(w, dumbbell, flat[0], 0, 1)};
  const int n2 = 15;
  hold_and_step(w, lifted, dumbbell, n2, dt);
  ASSERT_EQ(w.state.wall_contacts.size(), 1u);
  EXPECT_EQ(w.state.wall_contacts[0].sub, 0);
  EXPECT_NEAR(w.state.wall_contacts[0].xi.x(), (n1 + n2) * u * dt, 1e-6 * (n1 + n2) * u * dt);

  // Put it down again: piece 1 starts a new spring from zero.
  const int n3 = 7;
  hold_and_step(w, flat, dumbbell, n3, dt);
  ASSERT_EQ(w.state.wall_contacts.size(), 2u);
  EXPECT_NEAR(find_sub(w.state.wall_contacts, 0)->xi.x(), (n1 + n2 + n3) * u * dt, 1e-6 * (n1 + n2 + n3) * u * dt);
  EXPECT_NEAR(find_sub(w.state.wall_contacts, 1)->xi.x(), n3 * u * dt, 1e-9 * n3 * u * dt);
}

TEST(CompoundShape, TwoSpringsOnASlabGrainEachWithItsOwnHistory) {
  World w;
  w.model.gravity = Vec3::Zero();
  const Index mat = w.model.add_material(sticky());
  // A flat slab grain (convex polytope), top face at z = 0, in its principal frame.
  const double hx = 5e-3, hy = 2e-3, hz = 0.5e-3;
  const TriMesh box = box_mesh(hx, hy, hz);
  const Quat slab_q(mass_properties(box).principal_axes);
  const Index slab = w.add_body(w.model.add_mesh_shape(box, "slab"), mat, 1.0, Vec3(0, 0, -hz), slab_q);
  const Index dumbbell = w.add_body(add_dumbbell_shape(w.model), mat, 1.0, Vec3(0, 0, r - d));
  const double dt = 0.1 * w.critical_time_step();
  const std::vector<Pose> flat{{w.state.bodies[slab].x, w.state.bodies[slab].q},
                               {w.state.bodies[dumbbell].x, w.state.bodies[dumbbell].q}};

  const int n1 = 30;
  hold_and_step(w, flat, dumbbell, n1, dt);
  ASSERT_EQ(w.state.contacts.size(), 2u);
  EXPECT_EQ(touching_pair_count(w.state.contacts), 1u);
  for (int sub : {0, 1}) {
    const Contact* c = find_sub(w.state.contacts, sub);
    ASSERT_NE(c, nullptr) << "sub-contact " << sub;
    EXPECT_EQ(c->a, slab);
    EXPECT_EQ(c->b, dumbbell);
    EXPECT_NEAR(c->geo.normal.z(), 1.0, 1e-6);  // from the slab (a) to the dumbbell (b)
    EXPECT_NEAR(c->geo.depth, d, 1e-3 * d);
    EXPECT_NEAR(c->xi.x(), n1 * u * dt, 1e-6 * n1 * u * dt);
  }

  const std::vector<Pose> lifted{flat[0], tilted(w, dumbbell, flat[1], 1, 0)};
  const int n2 = 10;
  hold_and_step(w, lifted, dumbbell, n2, dt);
  ASSERT_EQ(w.state.contacts.size(), 1u);
  EXPECT_EQ(w.state.contacts[0].sub, 1);
  EXPECT_NEAR(w.state.contacts[0].xi.x(), (n1 + n2) * u * dt, 1e-6 * (n1 + n2) * u * dt);

  const int n3 = 5;
  hold_and_step(w, flat, dumbbell, n3, dt);
  ASSERT_EQ(w.state.contacts.size(), 2u);
  EXPECT_NEAR(find_sub(w.state.contacts, 0)->xi.x(), n3 * u * dt, 1e-6 * n3 * u * dt);
  EXPECT_NEAR(find_sub(w.state.contacts, 1)->xi.x(), (n1 + n2 + n3) * u * dt, 1e-6 * (n1 + n2 + n3) * u * dt);
}
