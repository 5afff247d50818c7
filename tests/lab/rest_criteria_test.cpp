// The rest test's kinetic energy (lab/rest_criteria.h): a sphere spinning on
// a frictionless floor keeps its spin exactly (the floor's force passes
// through its centre), so that spin is left out; on a frictional floor the
// spin about the floor's normal is left out too (a point contact's friction
// acts on slip, which that spin does not make), the rolling spin counts; for
// a faceted grain every spin counts.
#include "dynamics/world.h"
#include "geometry/primitives.h"
#include "lab/rest_criteria.h"

#include <gtest/gtest.h>

#include <cmath>

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

  // On a frictional floor: what counts is the motion and the spin about
  // horizontal axes (rolling, which the floor's friction brakes), as they are
  // after the step that found the contact.
  const auto counted = [&](const World& w) {
    const BodyState& b = w.state.bodies[0];
    return 0.5 * m.mass * b.v.squaredNorm() + 0.5 * m.inertia.x() * (b.w.x() * b.w.x() + b.w.y() * b.w.y());
  };
  SphereOnFloor twisting(0.3, v, spin);
  ASSERT_EQ(twisting.w.state.wall_contacts.size(), 1u);
  EXPECT_NEAR(packing_kinetic_energy(twisting.w), counted(twisting.w), 1e-12 * twisting.w.kinetic_energy());
  EXPECT_LT(packing_kinetic_energy(twisting.w), 1e-3 * twisting.spin_energy());  // the twist is left out

  SphereOnFloor rough(0.3, v, Vec3(600, 0, 800));  // rolling and twisting
  ASSERT_EQ(rough.w.state.wall_contacts.size(), 1u);
  EXPECT_NEAR(packing_kinetic_energy(rough.w), counted(rough.w), 1e-12 * rough.w.kinetic_energy());
  EXPECT_GT(packing_kinetic_energy(rough.w), 0.3 * rough.spin_energy());  // the rolling counts
}

// A sphere between two frictional contacts: on one line (opposite), the spin
// about that line is free; on two lines, every spin slides one of them.
TEST(RestCriteria, SpinAboutTheLineOfTwoOppositeContactsIsLeftOut) {
  const auto sandwich = [](double tilt) {
    World w;
    Material grain;
    grain.friction = 0.5;
    const Index mg = w.model.add_material(grain);
    const double r = 0.4e-3;
    const Index shape = w.model.add_sphere_shape(r);
    w.add_body(shape, mg, 1.0, Vec3::Zero(), Quat::Identity(), Vec3::Zero(), Vec3(0, 0, 700));
    const Vec3 up = Vec3(std::sin(tilt), 0, std::cos(tilt));
    w.add_body(shape, mg, 1.0, (2 * r - 1e-6) * up, Quat::Identity(), Vec3::Zero(), Vec3::Zero());
    w.add_body(shape, mg, 1.0, Vec3(0, 0, -(2 * r - 1e-6)), Quat::Identity(), Vec3::Zero(), Vec3::Zero());
    w.settings.skin = 0.2 * r;
    w.step(1e-9);
    return w;
  };
  const World line = sandwich(0.0), bent = sandwich(0.3);
  ASSERT_EQ(line.contact_count(), 2u);
  ASSERT_EQ(bent.contact_count(), 2u);
  // The middle sphere's spin about the line holds nearly all the energy; the
  // step that found the contacts set the three moving apart.
  const BodyModel& m = line.model.bodies[0];
  const double spin = 0.5 * m.inertia.x() * 700.0 * 700.0;
  EXPECT_GT(line.kinetic_energy(), 0.99 * spin);
  EXPECT_LT(packing_kinetic_energy(line), 1e-3 * spin);
  EXPECT_DOUBLE_EQ(packing_kinetic_energy(bent), bent.kinetic_energy());
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
