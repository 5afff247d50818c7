// Walls: boxes and planes collect the force grains put on them, and move as prescribed.
#include "dynamics/world.h"
#include "collision/narrowphase.h"
#include "geometry/primitives.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdint>
#include <utility>
#include <vector>

using namespace grainlab;

namespace {

Material soft_rough() {
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
  const Index m = w.model.add_material(soft_rough());
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
    Material mat = soft_rough();
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
  Material mat = soft_rough();
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

namespace {

// Steps w once and checks its wall contacts against every wall-grain pair
// collided by brute force on the poses the step's narrowphase sees: the same
// touching pairs with the same depths. Returns how many touch.
int step_against_brute_force(World& w, double dt) {
  std::vector<std::pair<std::pair<Index, Index>, double>> expected, found;
  for (std::size_t k = 0; k < w.model.walls.size(); ++k) {
    const WallState& ws = w.state.walls[k];
    for (std::size_t i = 0; i < w.state.bodies.size(); ++i) {
      const SphereShape s{w.state.bodies[i].x, w.model.bodies[i].radius};
      const ContactResult r = w.model.walls[k].kind == ShapeKind::Plane
                                  ? collide(PlaneShape{ws.x, ws.q * Vec3::UnitZ()}, s)
                                  : collide(BoxShape{ws.q.toRotationMatrix(), ws.x, w.model.walls[k].half}, s);
      if (r.touching) expected.push_back({{static_cast<Index>(k), static_cast<Index>(i)}, r.depth});
    }
  }
  w.step(dt);
  for (const Contact& c : w.state.wall_contacts) found.push_back({{c.a, c.b}, c.geo.depth});
  EXPECT_EQ(found, expected) << "step " << w.state.step;
  return static_cast<int>(expected.size());
}

}  // namespace

// A world of spheres keeps its wall-grain candidates between steps (World::
// broadphase); these check it against brute force.

TEST(Walls, KeptWallCandidatesOfSpheresFindEveryWallContactOfBruteForce) {
  // Grains flying about in a box whose walls shake; one wall is moved by hand
  // by 1.9 skins again and again, and one is turned.
  World w;
  Material mat = soft_rough();
  mat.youngs_modulus = 1e8;
  const Index m = w.model.add_material(mat);
  std::uint64_t seed = 12345;
  const auto uniform = [&seed] {  // a fixed LCG: the same grains on every platform
    seed = seed * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<double>(seed >> 11) * 0x1.0p-53;
  };
  const double side = 12e-3;
  for (int i = 0; i < 8; ++i)  // a lattice 1.5 mm apart, radii 0.4-0.7 mm: no overlaps, some walls near
    for (int j = 0; j < 8; ++j)
      for (int k = 0; k < 4; ++k) {
        const Vec3 x = 1.5e-3 * Vec3(i + 0.5, j + 0.5, k + 0.5);
        const Vec3 v = Vec3(uniform() - 0.5, uniform() - 0.5, uniform() - 0.5);  // m/s
        w.add_body(w.model.add_sphere_shape(0.4e-3 + 0.3e-3 * uniform()), m, 1.0, x, Quat::Identity(), v);
      }
  w.add_plane(Vec3::Zero(), Vec3::UnitZ(), m, "floor");
  const Vec3 half(1e-3, side, side);
  w.add_box_wall(Vec3(-1e-3, 0.5 * side, 0.5 * side), half, Quat::Identity(), m, "left");
  w.add_box_wall(Vec3(side + 1e-3, 0.5 * side, 0.5 * side), half, Quat::Identity(), m, "right");
  w.add_box_wall(Vec3(0.5 * side, -1e-3, 0.5 * side), Vec3(side, 1e-3, side), Quat::Identity(), m, "front");
  w.add_box_wall(Vec3(0.5 * side, side + 1e-3, 0.5 * side), Vec3(side, 1e-3, side), Quat::Identity(), m, "back");
  const double dt = 0.2 * w.critical_time_step();
  int touching = 0;
  for (int step = 0; step < 10000; ++step) {
    const double t = step * dt;
    w.state.walls[1].v = Vec3(0.2 * std::sin(2e3 * t), 0, 0);  // shaking walls, 0.1 mm amplitude
    w.state.walls[2].v = Vec3(0, 0.3 * std::cos(3e3 * t), 0);
    if (step % 500 == 250) w.state.walls[3].x.y() -= 1.9 * w.settings.skin;  // by hand, beyond the margin
    if (step == 7000) w.state.walls[1].q = Quat(Eigen::AngleAxisd(0.05, Vec3::UnitY()));
    touching += step_against_brute_force(w, dt);
  }
  EXPECT_FALSE(w.state.wall_x_at_rebuild.empty());  // the kept candidates were used
  EXPECT_LT(w.state.wall_pairs.size(), w.model.walls.size() * w.state.bodies.size() / 4);  // and are few
  EXPECT_GT(touching, 10000 * 5);  // grains keep hitting the walls (88,540 measured)
}

TEST(Walls, KeptWallCandidatesOfSpheresFollowAWallMovedInSmallSteps) {
  // Still grains, no gravity, at gaps of 0 to 3 skins from a wall that is
  // moved towards them by hand 0.45 skin at a time: each move alone is below
  // the half skin that finds the candidates again, so only the wall's own
  // displacement since they were found can tell.
  World w;
  const Index m = w.model.add_material(soft_rough());
  w.model.gravity = Vec3::Zero();
  const double r = 0.5e-3;
  for (int i = 0; i < 40; ++i) w.add_body(w.model.add_sphere_shape(r), m, 1.0, Vec3(0, 0, 2.5 * r * i));
  const Index wall = w.add_box_wall(Vec3(-r - 1e-3, 0, 0), Vec3(1e-3, 1e-2, 5e-2), Quat::Identity(), m, "pusher");
  const double dt = 0.2 * w.critical_time_step();
  step_against_brute_force(w, dt);  // sets the skin (0.2 r)
  const double skin = w.settings.skin;
  for (int i = 0; i < 40; ++i) w.state.bodies[i].x.x() = 3 * skin * i / 40.0;  // gap 0 to 3 skins
  w.state.rebuild_pairs = true;
  int touching = 0;
  for (int move = 0; move < 8; ++move) {
    w.state.walls[wall].x.x() += 0.45 * skin;
    touching += step_against_brute_force(w, dt);
  }
  EXPECT_GT(touching, 40);  // the wall reached most of them
}
