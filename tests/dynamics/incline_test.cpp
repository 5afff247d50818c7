// A block on an incline: it sticks below the friction angle atan(mu) and
// slides above it with a = g (sin theta - mu cos theta).
#include "dynamics/laws/registry.h"
#include "dynamics/world.h"
#include "geometry/primitives.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace grainlab;

namespace {

struct Slide {
  double displacement = 0;  // along the slope, over the measuring window (m)
  double acceleration = 0;  // fitted, along the slope (m/s^2)
};

// A 10 x 10 x 6 mm block resting flat on a plane tilted by theta about y.
Slide slide_block(double theta, double mu) {
  World w;
  w.model.law = contact_law<HertzMaterialLaw>();
  Material mat;
  mat.density = 2650;
  mat.youngs_modulus = 1e8;
  mat.poisson_ratio = 0.3;
  mat.restitution = 0.2;
  mat.friction = mu;
  const Index m = w.model.add_material(mat);
  const double hz = 3e-3;
  const Index shape = w.model.add_mesh_shape(box_mesh(5e-3, 5e-3, hz), "block");
  const Vec3 normal(std::sin(theta), 0, std::cos(theta));
  const Vec3 downhill(std::cos(theta), 0, -std::sin(theta));
  // The principal frame of the box may permute its axes: find the local axis
  // of the short side and turn it onto the plane normal.
  Vec3 extent = Vec3::Zero();
  for (const Vec3& v : w.model.shapes[shape].mesh.vertices) extent = extent.cwiseMax(v.cwiseAbs());
  int short_axis = 0;
  extent.minCoeff(&short_axis);
  const Quat q = Quat::FromTwoVectors(Vec3::Unit(short_axis), normal);
  w.add_body(shape, m, 1.0, normal * (hz * 0.999), q);
  w.add_plane(Vec3::Zero(), normal, m, "incline");
  const double dt = w.critical_time_step() * 0.2;

  // Settle onto the plane, then measure over a window. The drop from the
  // initial overlap slips the block near the friction angle: at 26 deg the
  // soft-depth face contact (a face is twice as stiff as one Hertz point)
  // slides 20, 10 and 1.1 um in the first three 10 ms and then not at all
  // (kinetic energy 1e-32 J from 40 ms on), so the window starts at 40 ms.
  const int settle = static_cast<int>(0.04 / dt), window = static_cast<int>(0.05 / dt);
  for (int i = 0; i < settle; ++i) w.step(dt);
  // Least-squares fit s(t) = s0 + v0 t + a t^2 / 2.
  Eigen::Matrix3d ata = Eigen::Matrix3d::Zero();
  Eigen::Vector3d atb = Eigen::Vector3d::Zero();
  const double s_start = w.state.bodies[0].x.dot(downhill);
  double s = s_start;
  for (int i = 0; i < window; ++i) {
    w.step(dt);
    const double t = (i + 1) * dt;
    s = w.state.bodies[0].x.dot(downhill);
    const Eigen::Vector3d row(1, t, 0.5 * t * t);
    ata += row * row.transpose();
    atb += row * s;
  }
  const Eigen::Vector3d coef = ata.ldlt().solve(atb);
  return {s - s_start, coef(2)};
}

}  // namespace

TEST(Incline, SticksBelowFrictionAngle) {
  const double mu = 0.5;
  for (double theta_deg : {10.0, 20.0, 25.0, 26.0}) {  // atan(0.5) = 26.57 deg
    const Slide r = slide_block(theta_deg * M_PI / 180, mu);
    EXPECT_LT(std::abs(r.displacement), 1e-6) << theta_deg << " deg: the block crept";
  }
}

TEST(Incline, SlidesAboveFrictionAngleWithCoulombAcceleration) {
  const double mu = 0.3;  // atan(0.3) = 16.7 deg
  for (double theta_deg : {20.0, 30.0, 40.0}) {
    const double theta = theta_deg * M_PI / 180;
    const Slide r = slide_block(theta, mu);
    const double expected = 9.81 * (std::sin(theta) - mu * std::cos(theta));
    std::printf("incline %.0f deg, mu %.1f: acceleration %.4f m/s^2, Coulomb %.4f\n", theta_deg, mu, r.acceleration, expected);
    EXPECT_NEAR(r.acceleration / expected, 1.0, 0.02) << theta_deg << " deg";
  }
}
