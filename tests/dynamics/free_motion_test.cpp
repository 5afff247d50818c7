// Bodies with no contacts: free fall and torque-free rotation.
#include "core/error.h"
#include "core/rng.h"
#include "dynamics/integrator.h"
#include "dynamics/world.h"
#include "geometry/primitives.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

using namespace grainlab;

TEST(FreeMotion, FreeFallFollowsTheDiscreteSolutionExactly) {
  // Semi-implicit Euler: v_n = v0 + n g dt, x_n = x0 + n v0 dt + g dt^2 n (n+1) / 2.
  World w;
  const Index s = w.model.add_sphere_shape(1e-3);
  const Vec3 x0(0.1, -0.2, 0.3), v0(0.5, 0.25, 2.0);
  w.add_body(s, 0, 1.0, x0, Quat::Identity(), v0);
  const double dt = 1e-4;
  const int n = 5000;
  for (int i = 0; i < n; ++i) w.step(dt);
  const Vec3 g = w.model.gravity;
  const Vec3 x = x0 + n * dt * v0 + 0.5 * dt * dt * n * (n + 1.0) * g;
  const Vec3 v = v0 + n * dt * g;
  EXPECT_LT((w.state.bodies[0].x - x).norm(), 1e-12);
  EXPECT_LT((w.state.bodies[0].v - v).norm(), 1e-12);
  // And it converges to the continuous parabola: error = g dt t / 2.
  const double t = n * dt;
  const Vec3 exact = x0 + v0 * t + 0.5 * g * t * t;
  EXPECT_NEAR((w.state.bodies[0].x - exact).norm(), 0.5 * g.norm() * dt * t, 1e-12);
}

TEST(FreeMotion, TorqueFreeAsymmetricBodyConservesMomentumAndEnergy) {
  World w;
  w.model.gravity = Vec3::Zero();
  // A box with three different principal moments, spinning near its unstable
  // intermediate axis (the tennis-racket flip): the hardest case.
  const Index s = w.model.add_mesh_shape(box_mesh(3e-3, 2e-3, 1e-3), "brick");
  const Vec3 w0 = Vec3(0.05, 10.0, 0.1);
  w.add_body(s, 0, 1.0, Vec3::Zero(), Quat(Eigen::AngleAxisd(0.3, Vec3(1, 2, 3).normalized())), Vec3::Zero(), w0);
  const auto angular_momentum = [&] {
    const BodyState& b = w.state.bodies[0];
    const Mat3 r = b.q.toRotationMatrix();
    return Vec3(r * w.model.bodies[0].inertia.cwiseProduct(r.transpose() * b.w));
  };
  const Vec3 l0 = angular_momentum();
  const double e0 = w.kinetic_energy();
  const double dt = 1e-3;  // |w| dt = 0.01 rad
  double max_energy_error = 0, max_axis_change = 0;
  Vec3 axis0 = w.state.bodies[0].q.conjugate() * w.state.bodies[0].w;
  for (int i = 0; i < 20000; ++i) {  // 200 rad: several flips
    w.step(dt);
    max_energy_error = std::max(max_energy_error, std::abs(w.kinetic_energy() - e0) / e0);
    const Vec3 local = w.state.bodies[0].q.conjugate() * w.state.bodies[0].w;
    max_axis_change = std::max(max_axis_change, (local - axis0).norm() / axis0.norm());
  }
  std::printf("torque-free brick, 20000 steps: |dL|/|L| = %.2e, max |dE|/E = %.2e\n",
              (angular_momentum() - l0).norm() / l0.norm(), max_energy_error);
  EXPECT_LT((angular_momentum() - l0).norm() / l0.norm(), 1e-10);
  EXPECT_LT(max_energy_error, 1e-3);
  // The flip really happened: the body-frame angular velocity swung far away.
  EXPECT_GT(max_axis_change, 1.0);
}

TEST(FreeMotion, RotationQuaternionMatchesSinAndCosOnBothSidesOfItsSeries) {
  // The series (|phi| < 0.1) and sin/cos (above) against the closed form in
  // long double, from 1e-12 rad to 3 rad.
  for (double angle = 1e-12; angle < 3; angle *= 1.07) {
    const Vec3 axis = Vec3(0.3, -0.5, 0.81).normalized();
    const Quat q = rotation_quaternion(angle * axis);
    const long double x = 0.5L * angle;
    const double c = static_cast<double>(std::cos(x)), s = static_cast<double>(std::sin(x));
    EXPECT_NEAR(q.w(), c, 3e-16) << angle;
    EXPECT_NEAR(q.vec().dot(axis), s, 4e-16 * s) << angle;
    EXPECT_NEAR(q.norm(), 1, 3e-16) << angle;
  }
}

TEST(FreeMotion, HalfwayIsSlerpAtOneHalf) {
  Rng rng(4);
  for (int t = 0; t < 200; ++t) {
    const Quat q0 = rng.rotation();
    Quat q1 = rotation_quaternion(rng.uniform(0, 2.5) * rng.unit_vector()) * q0;
    if (t % 2) q1.coeffs() = -q1.coeffs();  // the same rotation, the other sign
    const Quat h = halfway(q0, q1), ref = q0.slerp(0.5, q1);
    EXPECT_LT(std::min((h.coeffs() - ref.coeffs()).norm(), (h.coeffs() + ref.coeffs()).norm()), 1e-15) << t;
  }
}

TEST(FreeMotion, FourSpheresTurnAsOneSphereDoes) {
  // turn_spheres (lanes, a Newton step for 1/|q|) against the scalar turn
  // (a square root and a division): the same rotation to rounding, unit to
  // rounding, also after a million steps; lanes turned by 0.1 rad or more
  // and orientations far from unit take the scalar path.
  Rng rng(11);
  double worst = 0, worst_norm = 0;
  for (int t = 0; t < 2000; ++t) {
    Quat q[4], ref[4];
    Quat* ptr[4];
    Vec3 phi[4];
    for (int l = 0; l < 4; ++l) {
      q[l] = rng.rotation();
      const double angle = t % 7 == 0 && l == 2 ? rng.uniform(0.1, 2.0) : std::pow(10.0, rng.uniform(-12, -1.01));
      phi[l] = angle * rng.unit_vector();
      if (t % 11 == 0 && l == 1) q[l].coeffs() *= 1.5;  // not unit: the scalar path normalises it
      ref[l] = q[l];
      turn_sphere(ref[l], phi[l]);
      ptr[l] = &q[l];
    }
    turn_spheres(ptr, phi);
    for (int l = 0; l < 4; ++l) {
      const double d = std::min((q[l].coeffs() - ref[l].coeffs()).norm(), (q[l].coeffs() + ref[l].coeffs()).norm());
      worst = std::max(worst, d);
      worst_norm = std::max(worst_norm, std::abs(q[l].norm() - 1));
    }
  }
  EXPECT_LT(worst, 4e-16);
  EXPECT_LT(worst_norm, 4e-16);
  // A million steps of a spinning sphere (1e-3 rad a step): still unit, and
  // at the angle the rotation says.
  Quat q[4] = {Quat::Identity(), Quat::Identity(), Quat::Identity(), Quat::Identity()};
  Quat* ptr[4] = {&q[0], &q[1], &q[2], &q[3]};
  const Vec3 axis = Vec3(0.2, 0.6, -0.3).normalized();
  const Vec3 phi[4] = {1e-3 * axis, 1e-3 * axis, 1e-3 * axis, 1e-3 * axis};
  for (int i = 0; i < 1000000; ++i) turn_spheres(ptr, phi);
  EXPECT_NEAR(q[0].norm(), 1, 1e-15);
  EXPECT_NEAR(q[0].w(), std::cos(0.5 * 1000.0), 1e-9);  // 1000 rad in all
  EXPECT_NEAR(q[0].vec().dot(axis), std::sin(0.5 * 1000.0), 1e-9);
}

TEST(FreeMotion, ANonFiniteVelocityStopsTheStepNamingTheGrain) {
  // The step's check reads each body's |v|^2 + |w|^2: a NaN or infinite
  // velocity or angular velocity of any grain stops it with that grain named.
  for (int which = 0; which < 3; ++which) {
    World w;
    const Index s = w.model.add_sphere_shape(1e-3);
    for (int i = 0; i < 3; ++i) w.add_body(s, 0, 1.0, Vec3(0.01 * i, 0, 0));
    w.step(1e-7);
    BodyState& b = w.state.bodies[2];
    if (which == 0) b.v.x() = std::nan("");
    if (which == 1) b.w.z() = std::numeric_limits<double>::infinity();
    if (which == 2) b.v.y() = 1e300;  // finite, but its square overflows: caught, though every value is finite
    try {
      w.step(1e-7);
      FAIL() << "no error, case " << which;
    } catch (const RunError& e) {
      const std::string what = e.what();
      const char* expected = which == 2 ? "speeds overflow" : "grain 2 has a non-finite";
      EXPECT_NE(what.find(expected), std::string::npos) << what;
    }
  }
}
