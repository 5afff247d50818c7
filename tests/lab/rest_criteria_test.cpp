// The rest test's kinetic energy (lab/rest_criteria.h): a sphere spinning on
// a frictionless floor keeps its spin exactly (the floor's force passes
// through its centre), so that spin is left out; on a frictional floor, or
// for a faceted grain, it counts.
#include "dynamics/world.h"
#include "geometry/primitives.h"
#include "lab/rest_criteria.h"

#include <gtest/gtest.h>

using namespace grainlab;

namespace {

// A sphere of radius 0.4 mm pressed 1 um into the floor, moving at v and spinning at w.
struct SphereOnFloor {
  World w;
  explicit SphereOnFloor(double floor_friction, const Vec3& v, const Vec3& spin) {
    Material grain;
    grain.friction = 0.5;
    Material floor = grain;
    floor.friction = floor_friction;
    const Index mg = w.model.add_material(grain), mf = w.model.add_material(floor);
    const double r = 0.4e-3;
    w.add_body(w.model.add_sphere_shape(r), mg, 1.0, Vec3(0, 0, r - 1e-6), Quat::Identity(), v, spin);
    w.add_plane(Vec3::Zero(), Vec3::UnitZ(), mf, "floor");
    w.step(1e-9);  // finds the contact
  }
  double spin_energy() const {
    const BodyModel& m = w.model.bodies[0];
    return kinetic_energy_of(m, w.state.bodies[0]) - 0.5 * m.mass * w.state.bodies[0].v.squaredNorm();
  }
};

}  // namespace

TEST(RestCriteria, SpinThatNoContactCanBrakeIsLeftOut) {
  const Vec3 v(1e-3, 0, 0), spin(0, 0, 800);
  SphereOnFloor lubricated(0.0, v, spin);
  ASSERT_EQ(lubricated.w.state.wall_contacts.size(), 1u);
  const BodyModel& m = lubricated.w.model.bodies[0];
  EXPECT_GT(lubricated.spin_energy(), 1e3 * 0.5 * m.mass * v.squaredNorm());
  EXPECT_DOUBLE_EQ(packing_kinetic_energy(lubricated.w), 0.5 * m.mass * lubricated.w.state.bodies[0].v.squaredNorm());

  SphereOnFloor rough(0.3, v, spin);
  ASSERT_EQ(rough.w.state.wall_contacts.size(), 1u);
  EXPECT_DOUBLE_EQ(packing_kinetic_energy(rough.w), rough.w.kinetic_energy());
}

TEST(RestCriteria, FacetedGrainsSpinAlwaysCounts) {
  World w;
  Material grain;
  grain.friction = 0;
  const Index mg = w.model.add_material(grain);
  w.add_body(w.model.add_mesh_shape(box_mesh(0.4e-3, 0.3e-3, 0.2e-3), "box"), mg, 1.0, Vec3(0, 0, 1e-3),
             Quat::Identity(), Vec3::Zero(), Vec3(0, 0, 500));
  EXPECT_DOUBLE_EQ(packing_kinetic_energy(w), w.kinetic_energy());
  EXPECT_GT(w.kinetic_energy(), 0.0);
}
