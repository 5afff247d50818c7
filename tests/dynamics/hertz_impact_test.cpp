// Head-on impact of two spheres against the Hertz closed form.
//
// Elastic Hertz: m* x'' = -K x^{3/2}, K = (4/3) E* sqrt(R*). Energy gives the
// maximum overlap x_m = (5 m* v^2 / (4 K))^{2/5} and the duration
// t_c = 2 (x_m / v) \int_0^1 du / sqrt(1 - u^{5/2})
//     = 2 (x_m / v) sqrt(pi) Gamma(7/5) / Gamma(9/10).
#include "dynamics/laws/registry.h"
#include "dynamics/world.h"
#include "head_on_impact.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace grainlab;

namespace {

using testing_support::Impact;

// Two equal spheres closing at relative speed v, about steps_per_contact_estimate
// steps over the expected contact time t_estimate.
Impact simulate_impact(ContactLaw law, const Material& mat, double radius, double v,
                       double steps_per_contact_estimate, double t_estimate) {
  return testing_support::head_on_impact(law, mat, radius, v, t_estimate / steps_per_contact_estimate);
}

double hertz_duration(double m_eff, double r_eff, double e_star, double v) {
  const double k = 4.0 / 3.0 * e_star * std::sqrt(r_eff);
  const double x_m = std::pow(5.0 * m_eff * v * v / (4.0 * k), 0.4);
  return 2.0 * x_m / v * std::sqrt(M_PI) * std::tgamma(1.4) / std::tgamma(0.9);
}

Material glass() {
  Material m;
  m.density = 2500;
  m.youngs_modulus = 6e10;
  m.poisson_ratio = 0.25;
  m.restitution = 1.0;
  m.friction = 0.3;
  return m;
}

}  // namespace

TEST(HertzImpact, ElasticDurationMatchesClosedForm) {
  const Material mat = glass();
  const double r = 0.5e-3, v = 0.2;
  const double mass = mat.density * 4.0 / 3.0 * M_PI * r * r * r;
  const double e_star = mat.youngs_modulus / (2 * (1 - mat.poisson_ratio * mat.poisson_ratio));
  const double expected = hertz_duration(0.5 * mass, 0.5 * r, e_star, v);
  const Impact got = simulate_impact(contact_law<HertzMaterialLaw>(), mat, r, v, 400, expected);
  std::printf("Hertz (material) contact duration: measured / closed form = %.5f, restitution %.5f\n",
              got.duration / expected, got.restitution);
  EXPECT_NEAR(got.duration / expected, 1.0, 0.01);
  EXPECT_NEAR(got.restitution, 1.0, 0.01);
}

TEST(HertzImpact, UserFormWithoutDampingMatchesClosedForm) {
  // f_n = k_n sqrt(R* delta) delta = K delta^{3/2} with K = k_n sqrt(R*): E* = 3 k_n / 4.
  Material mat;
  mat.density = 2650;
  mat.k_n = 1e9;
  mat.k_t = 0;
  mat.gamma_n = mat.gamma_t = 0;
  const double r = 0.4e-3, v = 0.1;
  const double mass = mat.density * 4.0 / 3.0 * M_PI * r * r * r;
  const double expected = hertz_duration(0.5 * mass, 0.5 * r, 0.75 * mat.k_n, v);
  const Impact got = simulate_impact(contact_law<HertzUserLaw>(), mat, r, v, 400, expected);
  EXPECT_NEAR(got.duration / expected, 1.0, 0.01);
  EXPECT_NEAR(got.restitution, 1.0, 0.01);
}

class HertzRestitution : public ::testing::TestWithParam<double> {};

TEST_P(HertzRestitution, MeasuredEqualsRequested) {
  Material mat = glass();
  mat.restitution = GetParam();
  const double r = 0.5e-3;
  const double mass = mat.density * 4.0 / 3.0 * M_PI * r * r * r;
  const double e_star = mat.youngs_modulus / (2 * (1 - mat.poisson_ratio * mat.poisson_ratio));
  for (double v : {0.05, 0.5}) {  // restitution must not depend on the speed
    const double t = hertz_duration(0.5 * mass, 0.5 * r, e_star, v);
    const Impact got = simulate_impact(contact_law<HertzMaterialLaw>(), mat, r, v, 400, t);
    std::printf("restitution requested %.2f at %.2f m/s: measured %.5f\n", mat.restitution, v, got.restitution);
    EXPECT_NEAR(got.restitution / mat.restitution, 1.0, 0.01) << "v = " << v;
  }
}

INSTANTIATE_TEST_SUITE_P(Range, HertzRestitution, ::testing::Values(0.1, 0.3, 0.5, 0.7, 0.9));

TEST(HertzImpact, SphereOnWallRestitution) {
  Material mat = glass();
  mat.restitution = 0.6;
  World w;
  w.model.law = contact_law<HertzMaterialLaw>();
  w.model.gravity = Vec3::Zero();
  const Index m = w.model.add_material(mat);
  const double r = 0.5e-3, v = 0.3;
  w.add_body(w.model.add_sphere_shape(r), m, 1.0, Vec3(0, 0, r * 1.001), Quat::Identity(),
             Vec3(0, 0, -v));
  w.add_plane(Vec3::Zero(), Vec3::UnitZ(), m, "floor");
  const double dt = w.critical_time_step() / 50;
  for (int i = 0; i < 200000 && (w.state.bodies[0].v.z() < 0.0 || w.contact_count() > 0); ++i)
    w.step(dt);
  EXPECT_NEAR(w.state.bodies[0].v.z() / v, 0.6, 0.006);
}
