// Rotation angle of grains (Eq. 21 made robust): known rotations, the double
// cover, and small angles near identity.
#include "analysis/rotation.h"
#include "core/rng.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

using namespace grainlab;
using namespace grainlab::analysis;

namespace {

Quat about(const Vec3& axis, double angle) { return Quat(Eigen::AngleAxisd(angle, axis.normalized())); }

}  // namespace

TEST(Rotation, QuarterTurnsAboutAnyAxis) {
  const double half_pi = std::numbers::pi / 2;
  EXPECT_NEAR(rotation_angle(about(Vec3::UnitX(), half_pi)), half_pi, 1e-15);
  EXPECT_NEAR(rotation_angle(about(Vec3(1, 2, 3), half_pi)), half_pi, 1e-15);
  EXPECT_NEAR(rotation_angle(about(Vec3::UnitZ(), std::numbers::pi)), std::numbers::pi, 1e-15);
  EXPECT_EQ(rotation_angle(Quat::Identity()), 0.0);
  // 270 degrees one way is 90 degrees the other: the angle lies in [0, pi]
  // (Eq. 21 as printed, 2 acos(q0), would give 3 pi / 2).
  EXPECT_NEAR(rotation_angle(about(Vec3::UnitY(), 3 * half_pi)), half_pi, 1e-15);
}

TEST(Rotation, QAndMinusQAreTheSameRotation) {
  Rng rng(5);
  for (int k = 0; k < 100; ++k) {
    const Quat q = rng.rotation();
    const Quat minus(-q.w(), -q.x(), -q.y(), -q.z());
    EXPECT_EQ(rotation_angle(q), rotation_angle(minus));
    EXPECT_GE(rotation_angle(q), 0.0);
    EXPECT_LE(rotation_angle(q), std::numbers::pi);
  }
}

TEST(Rotation, SmallAnglesNearIdentityAreAccurate) {
  // 2 acos(q0) loses an angle of 1e-9 rad entirely (cos(5e-10) rounds to 1).
  for (double angle : {1e-12, 1e-9, 1e-6, 1e-3}) {
    const double got = rotation_angle(about(Vec3(0.3, -1, 0.2), angle));
    EXPECT_NEAR(got / angle, 1.0, 1e-12) << angle;
  }
  // The relative rotation of a randomly oriented grain that turned by 1e-8 rad.
  Rng rng(8);
  const Quat ref = rng.rotation();
  const Quat now = about(rng.unit_vector(), 1e-8) * ref;
  const double got = relative_rotation_angle(now, ref);
  std::printf("  relative rotation of 1e-8 rad measured as %.12e rad\n", got);
  EXPECT_NEAR(got, 1e-8, 1e-14);  // 2 acos(q0) is off by ~1e-8 here
}

TEST(Rotation, RelativeAngleIsTheAngleTurnedSinceTheReference) {
  Rng rng(9);
  const Quat ref = rng.rotation();
  const Quat turn = about(Vec3(1, 1, 0), 0.7);
  EXPECT_NEAR(relative_rotation_angle(turn * ref, ref), 0.7, 1e-14);  // turned in the world frame
  EXPECT_NEAR(relative_rotation_angle(ref * turn, ref), 0.7, 1e-14);  // turned in its own frame
  // A sign flip of the stored orientation is no rotation at all.
  const Quat flipped(-ref.w(), -ref.x(), -ref.y(), -ref.z());
  EXPECT_NEAR(relative_rotation_angle(flipped, ref), 0.0, 1e-14);
}

TEST(Rotation, MeanOverAllGrainsAndOverASubset) {
  State ref, now;
  ref.bodies.resize(4);
  now.bodies.resize(4);
  const double angles[4] = {0.1, 0.2, 0.3, 1.0};
  Rng rng(10);
  for (int i = 0; i < 4; ++i) {
    ref.bodies[i].q = rng.rotation();
    now.bodies[i].q = about(rng.unit_vector(), angles[i]) * ref.bodies[i].q;
  }
  const std::vector<double> theta = rotation_angles(now, ref);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(theta[i], angles[i], 1e-14);
  EXPECT_NEAR(mean_rotation_angle(now, ref), 0.4, 1e-14);
  const GrainMask band = mask_of(4, std::vector<Index>{1, 3});
  EXPECT_NEAR(mean_rotation_angle(now, ref, &band), 0.6, 1e-14);
  const GrainMask none(4, 0);
  EXPECT_TRUE(std::isnan(mean_rotation_angle(now, ref, &none)));
  State other;
  other.bodies.resize(3);
  EXPECT_THROW(rotation_angles(other, ref), std::invalid_argument);
}
