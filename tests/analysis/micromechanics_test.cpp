// The end-of-run summary (analysis/micromechanics.h) and the force segments
// (analysis/force_chains.h) on hand-built states.
#include "analysis/force_chains.h"
#include "analysis/micromechanics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

using namespace grainlab;
using namespace grainlab::analysis;

TEST(MicromechanicsSummary, SpheresAreRoundAndTheStressIsOverTheBoxVolume) {
  // Two unit-spaced spheres pressed together along z by 10 N: sigma_zz = F l / V.
  Model model;
  model.shapes.push_back(Shape{});  // a sphere
  model.bodies.resize(2);
  State s;
  s.bodies.resize(2);
  s.bodies[1].x = Vec3(0, 0, 1e-3);
  Contact pc;
  pc.a = 0, pc.b = 1;
  pc.geo.touching = true;
  pc.geo.normal = Vec3::UnitZ();
  pc.force = Vec3(0, 0, 10);
  pc.normal_force = 10;
  s.contacts = {pc};
  const MicromechanicsSummary m = micromechanics_summary(model, s, 0.02 * 0.01 * 0.005, std::vector<double>{0.1, 0.4},
                                                         {});
  ASSERT_TRUE(m.mean_roundness.has_value());
  EXPECT_EQ(*m.mean_roundness, 1.0);
  EXPECT_EQ(m.peak_fabric_psi, 0.4);
  EXPECT_FALSE(m.peak_fabric_psi_band.has_value());
  EXPECT_DOUBLE_EQ(m.specimen_volume, 0.02 * 0.01 * 0.005);
  EXPECT_DOUBLE_EQ(m.love_weber.sigma(2, 2), 10 * 1e-3 / m.specimen_volume);
  EXPECT_FALSE(mean_grain_roundness(Model{}).has_value());
}

TEST(ForceSegments, CentresNormalAndTangentialForce) {
  State s;
  s.bodies.resize(3);
  s.bodies[1].x = Vec3(1, 0, 0);
  Contact touching, apart;
  touching.a = 0, touching.b = 1;
  touching.geo.touching = true;
  touching.geo.normal = Vec3(2, 0, 0);  // not unit: normalised
  touching.force = Vec3(3, 4, 0);       // 3 N along the normal, 4 N across
  touching.normal_force = 3;
  apart.a = 1, apart.b = 2;
  s.contacts = {touching, apart};
  const std::vector<ForceSegment> seg = force_segments(s);
  ASSERT_EQ(seg.size(), 1u);
  EXPECT_EQ(seg[0].a, Vec3(0, 0, 0));
  EXPECT_EQ(seg[0].b, Vec3(1, 0, 0));
  EXPECT_EQ(seg[0].normal_force, 3.0);
  EXPECT_DOUBLE_EQ(seg[0].tangential_force, 4.0);
}

TEST(ForceSegments, StrongAboveTheMeanNormalForce) {
  State s;
  s.bodies.resize(4);
  std::vector<Contact> pairs(3);
  const double forces[] = {1, 5, 2};  // mean 8/3: only the 5 N contact is strong
  for (int k = 0; k < 3; ++k) {
    pairs[k].a = k, pairs[k].b = k + 1;
    pairs[k].geo.touching = true;
    pairs[k].geo.normal = Vec3::UnitX();
    pairs[k].normal_force = forces[k];
    pairs[k].force = Vec3(forces[k], 0, 0);
  }
  s.contacts = pairs;
  const std::vector<ForceSegment> seg = force_segments(s);
  ASSERT_EQ(seg.size(), 3u);
  EXPECT_FALSE(seg[0].strong);
  EXPECT_TRUE(seg[1].strong);
  EXPECT_FALSE(seg[2].strong);
}
