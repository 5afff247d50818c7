// The faceted contact is conservative (collision/soft_depth.h): the pair's
// potential is u(D), D the soft depth of the edges inside the other shape,
// and the wrench it returns is exactly minus the gradient of D with respect
// to B's pose, per unit u'(D):
//     dD/dx_B     = -gain n,
//     dD/dtheta_B = -((point - c_B) x gain n + twist)   (B turned about its centre).
// Checked by central differences of D on random hull pairs of all kinds of
// contact (vertex on face, edge on face, edge across edge, face on face), and
// analytically for two edges crossing, where no vertex is inside either shape.
#include "collision/gjk.h"
#include "collision/narrowphase.h"
#include "collision/soft_depth.h"
#include "test_shapes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace grainlab;
using namespace grainlab::testing;

namespace {

// A cold collision (GJK/EPA, then the patch): D as a function of the poses only.
ContactResult cold(const PolytopeShape& a, const PolytopeShape& b, const Vec3& u) {
  Vec3 dir = u;
  return collide_convex(a, b, dir, false);
}

bool soft(const ContactResult& r) { return r.touching && !(r.gain == 1.0 && r.spread == 0.0); }

}  // namespace

TEST(SoftDepthGradient, WrenchIsMinusTheGradientOfTheSoftDepth) {
  Rng rng(81);
  int checked = 0;
  double worst_force = 0, worst_torque = 0;
  for (int run = 0; run < 120; ++run) {
    Vec3 u;
    const int nverts = run % 3 == 0 ? 8 : run % 3 == 1 ? 30 : 200;
    const double delta = rng.uniform(1e-6, 3e-5);  // penetration along the closest direction, ~1 mm hulls
    BlobPair p = make_blob_pair(rng, nverts, -1e-5, u);
    Vec3 n = u;
    const ContactResult apart = gjk_epa(p.a, p.b, n);
    p.b.pos += (apart.depth - delta) * n;  // from 'apart' to overlapping by delta along n
    const ContactResult r = cold(p.a, p.b, u);
    if (!soft(r)) continue;
    const double L = p.b.scale;
    const Vec3 force = r.gain * r.normal;
    const Vec3 torque = (r.point - p.b.pos).cross(force) + r.twist;
    const double h = 1e-10;  // m, and h / L rad
    Vec3 fd_force, fd_torque;
    bool all_soft = true;
    for (int axis = 0; axis < 3; ++axis) {
      const Vec3 e = Vec3::Unit(axis);
      PolytopeShape plus = p.b, minus = p.b;
      plus.pos += h * e, minus.pos -= h * e;
      const ContactResult rp = cold(p.a, plus, u), rm = cold(p.a, minus, u);
      all_soft = all_soft && soft(rp) && soft(rm);
      fd_force[axis] = -(rp.depth - rm.depth) / (2 * h);
      plus = p.b, minus = p.b;
      plus.rot = Eigen::AngleAxisd(h / L, e).toRotationMatrix() * p.b.rot;
      minus.rot = Eigen::AngleAxisd(-h / L, e).toRotationMatrix() * p.b.rot;
      const ContactResult tp = cold(p.a, plus, u), tm = cold(p.a, minus, u);
      all_soft = all_soft && soft(tp) && soft(tm);
      fd_torque[axis] = -(tp.depth - tm.depth) / (2 * h / L);
    }
    if (!all_soft) continue;  // the point contact took over somewhere: not this test's subject
    ++checked;
    const double ef = (fd_force - force).norm() / force.norm();
    const double et = (fd_torque - torque).norm() / (L * force.norm());
    worst_force = std::max(worst_force, ef);
    worst_torque = std::max(worst_torque, et);
    EXPECT_LT(ef, 1e-4) << "run " << run << " force " << force.transpose() << " fd " << fd_force.transpose();
    EXPECT_LT(et, 1e-4) << "run " << run << " torque " << torque.transpose() << " fd " << fd_torque.transpose();
  }
  std::printf("soft-depth gradient: %d pairs, worst relative error force %.2g, torque %.2g\n", checked, worst_force,
              worst_torque);
  EXPECT_GT(checked, 90);
}

// Two cubes turned 45 degrees so that A's top edge (along x) crosses B's
// bottom edge (along y) with a vertical overlap delta: no vertex of either is
// inside the other. Along A's edge the depth inside B is the tent
// (delta - |x|)/sqrt 2 for |x| < delta, and the same for B's edge inside A,
// so S_j = 4 (delta/sqrt 2)^j delta/(j+1) and D = kappa (k+1)/(k+2) delta/sqrt 2
// = delta/sqrt 2; the force is vertical, through the crossing, with no twist.
TEST(SoftDepthGradient, EdgesCrossingWithNoVertexInsideHaveTheTentDepth) {
  const double a = 1e-3;
  const TestHull cube = box_hull(Vec3(a, a, a));
  const Mat3 ra = Eigen::AngleAxisd(std::numbers::pi / 4, Vec3::UnitX()).toRotationMatrix();
  const Mat3 rb = Eigen::AngleAxisd(std::numbers::pi / 4, Vec3::UnitY()).toRotationMatrix();
  for (const double delta : {1e-7, 1e-6, 1e-5}) {
    const PolytopeShape pa{&cube.poly, ra, Vec3::Zero(), 1.0};
    const PolytopeShape pb{&cube.poly, rb, Vec3(0, 0, 2 * std::sqrt(2.0) * a - delta), 1.0};
    const ContactResult r = cold(pa, pb, Vec3(0.1, 0.2, 1).normalized());
    ASSERT_TRUE(soft(r)) << "delta " << delta;
    EXPECT_NEAR(r.depth, delta / std::sqrt(2.0), 1e-9 * delta);
    EXPECT_NEAR(r.normal.z(), 1.0, 1e-9);
    EXPECT_LT(std::hypot(r.point.x(), r.point.y()), 1e-9 * a);
    EXPECT_LT(r.twist.norm(), 1e-9 * a);
  }
}
