// The critical time step: a step above it is refused with a useful message.
#include "dynamics/laws/registry.h"
#include "core/error.h"
#include "dynamics/time_step.h"
#include "dynamics/world.h"
#include "geometry/convex_decomposition.h"
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

// The damped bound of time_step.h, checked on the step's own recurrence:
// forces from x_n and v_n, then v_{n+1} = v_n + (F/m) dt, x_{n+1} = x_n + v_{n+1} dt
// (World::forces then World::integrate). Just below the bound an oscillation
// decays; just above it grows, even far below the undamped limit 2/omega.
namespace {
double amplitude_after(double omega_dt, double zeta, int steps) {
  const double m = 1, k = 1;  // omega = 1: dt = omega_dt
  const double c = 2 * zeta * std::sqrt(k * m), dt = omega_dt;
  double x = 1, v = 0;
  for (int i = 0; i < steps; ++i) {
    v += (-k * x - c * v) / m * dt;
    x += v * dt;
  }
  return std::hypot(x, v);
}
}  // namespace

TEST(TimeStep, DampedBoundSeparatesDecayFromGrowth) {
  for (double zeta : {0.0, 0.2, 0.37, 0.8, 2.0}) {
    const double bound = damped_critical_step(1.0, 2 * zeta, 1.0);  // k = m = 1
    EXPECT_NEAR(bound, 2 * (std::sqrt(1 + zeta * zeta) - zeta), 1e-12);
    const int steps = 5000;
    // Below: damped motion decays; undamped motion stays bounded (its
    // invariant ellipse is long at omega dt near 2, so |(x, v)| reaches ~5).
    EXPECT_LT(amplitude_after(0.98 * bound, zeta, steps), zeta > 0 ? 1.0 : 10.0)
        << "zeta " << zeta << ": bounded below the bound";
    // Above: it grows without bound (or overflows to inf/nan).
    EXPECT_FALSE(amplitude_after(1.02 * bound, zeta, steps) < 1e6) << "zeta " << zeta << ": grows above it";
  }
  // With damping the limit is well below the undamped 2/omega.
  EXPECT_LT(damped_critical_step(1.0, 2 * 0.8, 1.0), 0.5 * 2.0);
}

TEST(TimeStep, CriticalStepIncludesTheContactDamping) {
  // A Hooke sphere on a wall: point mass m_c = m / 3.5 (rotation), C_n = gamma_n m.
  const auto estimate = [](double gamma_n) {
    World w;
    w.model.law = contact_law<HookeLaw>();
    Material m;
    m.density = 2500;
    m.k_n = 1e4;
    m.k_t = 0;
    m.gamma_n = gamma_n;
    const Index mat = w.model.add_material(m);
    w.add_body(w.model.add_sphere_shape(1e-3), mat, 1.0, Vec3::Zero());
    w.add_plane(Vec3(0, 0, -1e-3), Vec3::UnitZ(), mat, "floor");
    const double mass = w.model.bodies[0].mass;
    return std::pair{w.critical_time_step(), damped_critical_step(1e4, gamma_n * mass, mass / 3.5)};
  };
  const auto [undamped, undamped_expected] = estimate(0);
  const auto [damped, damped_expected] = estimate(5e4);
  EXPECT_NEAR(undamped, undamped_expected, 1e-12 * undamped_expected);
  EXPECT_NEAR(damped, damped_expected, 1e-12 * damped_expected);
  EXPECT_LT(damped, 0.6 * undamped);
}

TEST(TimeStep, ConcaveGrainsStepIncludesTheContactDampingConvexOnesDoNot) {
  // A U-shaped grain (collided as convex pieces) and its convex hull, each
  // alone on a wall, Hooke law: point mass m_c = 1 / (1/m + r^2 / I_min),
  // C_n = gamma_n m. The concave grain's bound is the damped one
  // (time_step.h: several contacts of one pair at once, measured unstable
  // without it); the convex grain keeps the undamped 2 sqrt(m_c / k).
  const TriMesh u = prism_mesh({{-3, 0}, {3, 0}, {3, 3}, {2, 3}, {2, 1}, {-2, 1}, {-2, 3}, {-3, 3}}, 1.0);
  TriMesh mesh = u;
  for (Vec3& v : mesh.vertices) v *= 1e-3;
  const double k_n = 1e4, gamma_n = 5e4;
  for (const bool concave : {true, false}) {
    World w;
    w.model.law = contact_law<HookeLaw>();
    Material m;
    m.density = 2500;
    m.k_n = k_n;
    m.k_t = 0;
    m.gamma_n = gamma_n;
    const Index mat = w.model.add_material(m);
    const Index shape = concave ? w.model.add_concave_shape(mesh, decompose_convex(mesh), "u")
                                : w.model.add_mesh_shape(mesh, "hull");
    w.add_body(shape, mat, 1.0, Vec3::Zero());
    w.add_plane(Vec3(0, 0, -5e-3), Vec3::UnitZ(), mat, "floor");
    const BodyModel& b = w.model.bodies[0];
    const double m_c = 1.0 / (b.inv_mass + b.bounding_radius * b.bounding_radius * b.inv_inertia.maxCoeff());
    const double expected = damped_critical_step(k_n, concave ? gamma_n * b.mass : 0.0, m_c);
    EXPECT_NEAR(w.critical_time_step(), expected, 1e-12 * expected) << (concave ? "concave" : "convex");
    if (concave) {
      EXPECT_LT(expected, 0.9 * damped_critical_step(k_n, 0.0, m_c));
    }
  }
}
