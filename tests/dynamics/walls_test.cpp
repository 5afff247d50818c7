// Walls: boxes and planes collect the force grains put on them, and move as prescribed.
#include "dynamics/world.h"
#include "geometry/primitives.h"

#include <gtest/gtest.h>

using namespace grainlab;

namespace {

Material soft() {
  Material m;
  m.youngs_modulus = 1e7;
  m.restitution = 0.2;
  m.friction = 0.5;
  return m;
}

// Lets a body come to rest on whatever is below it; returns the world.
void settle(World& w, double seconds) {
  const double dt = 0.2 * w.critical_time_step();
  for (double t = 0; t < seconds; t += dt) w.step(dt);
}

}  // namespace

TEST(Walls, ConvexGrainRestingOnABoxWallLoadsItWithItsWeight) {
  World w;
  const Index m = w.model.add_material(soft());
  const Index s = w.model.add_mesh_shape(icosphere(1e-3, 3), "ball");
  w.add_body(s, m, 1.0, Vec3(0, 0, 1.0005e-3));
  w.add_box_wall(Vec3(0, 0, -1e-3), Vec3(5e-3, 5e-3, 1e-3), Quat::Identity(), m, "slab");
  settle(w, 0.1);
  const double weight = w.model.bodies[0].gravity_mass * 9.81;
  EXPECT_NEAR(w.state.walls[0].force.z() / -weight, 1.0, 1e-4);
  EXPECT_LT(w.state.bodies[0].v.norm(), 1e-6);
}

TEST(Walls, SphereOnARotatedBoxWallAgreesWithAPlane) {
  // A sphere resting on the top face of a tilted box, and on the plane of that
  // face, comes to the same height.
  const Quat tilt(Eigen::AngleAxisd(0.2, Vec3::UnitX()));
  const Vec3 up = tilt * Vec3::UnitZ();
  double heights[2];
  for (int k = 0; k < 2; ++k) {
    World w;
    Material mat = soft();
    mat.friction = 2.0;  // sticks on the slope
    const Index m = w.model.add_material(mat);
    w.add_body(w.model.add_sphere_shape(1e-3), m, 1.0, up * 1.0001e-3);
    if (k == 0)
      w.add_box_wall(-up * 2e-3, Vec3(1e-2, 1e-2, 2e-3), tilt, m, "box");
    else
      w.add_plane(Vec3::Zero(), up, m, "plane");
    settle(w, 0.1);
    heights[k] = w.state.bodies[0].x.dot(up);
  }
  EXPECT_NEAR(heights[0], heights[1], 1e-9);
  EXPECT_LT(heights[0], 1e-3);  // it sank into the wall by the Hertz overlap
}

TEST(Walls, MovingWallKicksAGrainWithRestitution) {
  // A box wall moving at constant speed u along x hits a sphere lying on a
  // frictionless floor. In the wall's frame the sphere arrives at -u and
  // leaves at +e u: in the lab it moves off at (1 + e) u, ahead of the wall.
  World w;
  Material mat = soft();
  mat.friction = 0;
  const Index m = w.model.add_material(mat);
  w.add_body(w.model.add_sphere_shape(1e-3), m, 1.0, Vec3(0, 0, 1e-3));
  w.add_plane(Vec3::Zero(), Vec3::UnitZ(), m, "floor");
  const Index pusher = w.add_box_wall(Vec3(-2.0005e-3, 0, 1e-3), Vec3(1e-3, 5e-3, 5e-3), Quat::Identity(), m, "pusher");
  w.state.walls[pusher].v = Vec3(0.01, 0, 0);
  const double dt = w.critical_time_step() / 50;  // resolve the impact finely
  while (w.state.time < 0.05) w.step(dt);
  EXPECT_NEAR(w.state.walls[pusher].x.x(), -2.0005e-3 + 0.01 * w.state.time, 1e-12);
  EXPECT_NEAR(w.state.bodies[0].v.x() / 0.01, 1.0 + mat.restitution, 0.01);
  EXPECT_GT(w.state.bodies[0].x.x() - w.state.walls[pusher].x.x(), 1e-3 + 1e-5);  // ahead of the wall
}
