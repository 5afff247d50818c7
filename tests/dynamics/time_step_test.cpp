// The critical time step: a step above it is refused with a useful message.
#include "dynamics/laws/registry.h"
#include "core/error.h"
#include "dynamics/world.h"
#include "geometry/primitives.h"

#include <gtest/gtest.h>

using namespace grainlab;

TEST(TimeStep, PaperTable1StepIsRefusedForRealQuartzGrains) {
  // Table 1: k_n = 1e12, k_t = 8e11, gamma_n = 40, gamma_t = 20, dt = 1e-5 s,
  // for 0.707-0.841 mm grains of density 2650: unstable.
  World w;
  w.model.law = contact_law<HertzUserLaw>();
  Material m;
  m.density = 2650;
  m.k_n = 1e12;
  m.k_t = 8e11;
  m.gamma_n = 40;
  m.gamma_t = 20;
  m.friction = 0.19;
  const Index mat = w.model.add_material(m);
  const Index s = w.model.add_mesh_shape(icosphere(0.387e-3, 2), "grain");
  w.add_body(s, mat, 1.0, Vec3::Zero());
  w.add_plane(Vec3(0, 0, -1e-3), Vec3::UnitZ(), mat, "floor");
  try {
    w.step(1e-5);
    FAIL() << "an unstable step was accepted";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("critical"), std::string::npos) << msg;
    EXPECT_NE(msg.find("density"), std::string::npos) << "the message should suggest density scaling: " << msg;
  }
  EXPECT_LT(w.critical_time_step(), 1e-6);
  EXPECT_NO_THROW(w.step(0.5 * w.critical_time_step()));
}

TEST(TimeStep, DensityScalingRaisesTheCriticalStepBySquareRoot) {
  World w;
  const Index s = w.model.add_sphere_shape(1e-3);
  w.add_body(s, 0, 1.0, Vec3::Zero());
  w.add_plane(Vec3(0, 0, -2e-3), Vec3::UnitZ());
  const double before = w.critical_time_step();
  w.model.density_scale = 100;
  w.model.rescale_bodies();
  EXPECT_NEAR(w.critical_time_step() / before, 10.0, 1e-9);
}

TEST(TimeStep, NoPossibleContactSetsNoLimit) {
  World w;
  w.add_body(w.model.add_sphere_shape(1e-3), 0, 1.0, Vec3::Zero());
  EXPECT_TRUE(std::isinf(w.critical_time_step()));
  w.add_plane(Vec3(0, 0, -2e-3), Vec3::UnitZ());
  EXPECT_FALSE(std::isinf(w.critical_time_step()));
}

TEST(TimeStep, NonPositiveStepIsRefused) {
  World w;
  w.add_body(w.model.add_sphere_shape(1e-3), 0, 1.0, Vec3::Zero());
  EXPECT_THROW(w.step(0.0), InputError);
  EXPECT_THROW(w.step(-1e-6), InputError);
}
