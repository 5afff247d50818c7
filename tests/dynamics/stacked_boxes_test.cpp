// A small box resting face-down, off-centre, on a larger box on a plane: the
// stack settles (kinetic energy decays) and the box-box contact point stays
// put, at the centroid of the overlap (the small box's footprint).
#include "dynamics/laws/registry.h"
#include "dynamics/world.h"
#include "geometry/primitives.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace grainlab;

namespace {

// Orientation taking the shape's principal frame onto the world axes of the box
// with half sides `half` (all distinct).
Quat box_orientation(const World& w, Index shape, const Vec3& half) {
  Vec3 extent = Vec3::Zero();
  for (const Vec3& v : w.model.shapes[shape].mesh.vertices) extent = extent.cwiseMax(v.cwiseAbs());
  Mat3 r = Mat3::Zero();
  for (int i = 0; i < 3; ++i) {
    int j = 0;
    (half.array() - extent[i]).abs().minCoeff(&j);
    r(j, i) = 1;
  }
  if (r.determinant() < 0) r.col(0) = -r.col(0);
  return Quat(r);
}

}  // namespace

TEST(StackedBoxes, SettleWithContactPointAtOverlapCentroid) {
  World w;
  w.model.law = contact_law<HertzMaterialLaw>();
  Material mat;
  mat.density = 2650;
  mat.youngs_modulus = 1e8;
  mat.poisson_ratio = 0.3;
  mat.restitution = 0.2;
  mat.friction = 0.5;
  const Index m = w.model.add_material(mat);
  const Vec3 hb(6e-3, 5e-3, 3e-3), ht(2.5e-3, 2e-3, 1.5e-3);
  const Index big = w.model.add_mesh_shape(box_mesh(hb.x(), hb.y(), hb.z()), "big");
  const Index small = w.model.add_mesh_shape(box_mesh(ht.x(), ht.y(), ht.z()), "small");
  w.add_plane(Vec3::Zero(), Vec3::UnitZ(), m, "floor");
  w.add_body(big, m, 1.0, Vec3(0, 0, hb.z() * 0.9999), box_orientation(w, big, hb));
  const Vec3 offset(2.5e-3, -1.8e-3, 0);
  w.add_body(small, m, 1.0, offset + Vec3(0, 0, 2 * hb.z() + ht.z() + 2e-6), box_orientation(w, small, ht));
  const double dt = w.critical_time_step() * 0.2;

  double peak = 0;
  const int steps = static_cast<int>(0.15 / dt);
  for (int i = 0; i < steps; ++i) {
    w.step(dt);
    peak = std::max(peak, w.kinetic_energy());
  }
  EXPECT_LT(w.kinetic_energy(), 1e-6 * peak);

  // At rest: the box-box contact point holds still, at the footprint centroid.
  ASSERT_EQ(w.state.contacts.size(), 1u);
  double jump = 0;
  Vec3 last = w.state.contacts[0].geo.point;
  for (int i = 0; i < 200; ++i) {
    w.step(dt);
    ASSERT_TRUE(w.state.contacts[0].geo.touching);
    jump = std::max(jump, (w.state.contacts[0].geo.point - last).norm());
    last = w.state.contacts[0].geo.point;
  }
  EXPECT_LT(jump, 1e-6);
  const Vec3 top = w.state.bodies[1].x;
  EXPECT_NEAR(last.x(), top.x(), 0.03 * 2 * ht.y());
  EXPECT_NEAR(last.y(), top.y(), 0.03 * 2 * ht.y());
  EXPECT_GT(w.state.contacts[0].geo.spread, 1e-7);
}
