// Head-on impact of two spheres with the Hooke law against the closed form.
//
// The overlap x of two spheres approaching at relative speed v obeys, while
// they touch, m* x'' = -f_n with f_n = k x + C_n x', C_n = gamma m*:
//     x'' + gamma x' + w0^2 x = 0,   w0^2 = k / m*,   x(0) = 0, x'(0) = v.
// Underdamped (gamma < 2 w0), with w_d = sqrt(w0^2 - (gamma/2)^2):
//     x(t)  = (v / w_d) exp(-gamma t/2) sin(w_d t),
//     x'(t) = v exp(-gamma t/2) (cos(w_d t) - (gamma / (2 w_d)) sin(w_d t)).
// Undamped: the contact lasts pi / w0 = pi sqrt(m*/k) and the spheres leave
// at v (restitution 1). Damped, x returns to 0 at t = pi / w_d with speed
// v exp(-gamma pi / (2 w_d)): the textbook restitution. But the law never
// pulls (f_n >= 0), and f_n = m* (w0^2 x + gamma x') reaches 0 first, at
//     tan(w_d t_f) = -gamma w_d / (w_d^2 - gamma^2/4),   t_f in (pi/(2 w_d), pi/w_d);
// from there no force acts, so the spheres part at the speed they have then,
// e = -x'(t_f) / v, and stop touching when x reaches 0, at
// t_c = t_f + x(t_f) / (-x'(t_f)).
//
// Tolerances from the step dt: contact begins and ends between two steps, so
// the counted duration is off by at most 2 dt; semi-implicit Euler keeps a
// shadow energy that differs from the true one by a term in x x' dt, which
// vanishes where the contact starts (x = 0), so the exit speed is off by
// O((w0 dt)^2) plus the O(w0 dt) of the phase at which the clamp is met:
// 2 w0 dt bounds both (about 0.6 % at 1000 steps per contact).
#include "dynamics/laws/registry.h"
#include "dynamics/world.h"
#include "head_on_impact.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

using namespace grainlab;

namespace {

using testing_support::Impact;

// Two equal Hooke spheres approach head-on at relative speed v; dt as given.
Impact simulate_impact(const Material& mat, double radius, double v, double dt) {
  return testing_support::head_on_impact(contact_law<HookeLaw>(), mat, radius, v, dt);
}

// The closed form above for gamma < 2 w0 (gamma = 0 included).
Impact hooke_impact(double m_eff, double k, double gamma, double v) {
  const double w0 = std::sqrt(k / m_eff);
  const double wd = std::sqrt(w0 * w0 - 0.25 * gamma * gamma);
  if (gamma == 0) return {std::numbers::pi / w0, 1.0};
  const double t_f = (std::numbers::pi - std::atan2(gamma * wd, wd * wd - 0.25 * gamma * gamma)) / wd;
  const double decay = std::exp(-0.5 * gamma * t_f);
  const double x = v / wd * decay * std::sin(wd * t_f);
  const double x_dot = v * decay * (std::cos(wd * t_f) - 0.5 * gamma / wd * std::sin(wd * t_f));
  return {t_f + x / -x_dot, -x_dot / v};
}

Material hooke_material(double k_n, double gamma_n) {
  Material m;
  m.density = 2500;
  m.k_n = k_n;
  m.k_t = 0;
  m.gamma_n = gamma_n;
  m.gamma_t = 0;
  return m;
}

constexpr double kRadius = 0.5e-3, kSpeed = 0.1, kStepsPerContact = 1000;

double sphere_mass(const Material& m) { return m.density * 4.0 / 3.0 * std::numbers::pi * std::pow(kRadius, 3); }

}  // namespace

TEST(HookeImpact, UndampedDurationIsPiSqrtMOverK) {
  const Material mat = hooke_material(1e4, 0);
  const double m_eff = 0.5 * sphere_mass(mat);
  const double t_c = std::numbers::pi * std::sqrt(m_eff / mat.k_n);
  const double dt = t_c / kStepsPerContact;
  const Impact got = simulate_impact(mat, kRadius, kSpeed, dt);
  std::printf("Hooke undamped: duration / pi sqrt(m*/k) = %.6f, restitution %.6f\n", got.duration / t_c,
              got.restitution);
  EXPECT_NEAR(got.duration, t_c, 2 * dt);
  EXPECT_NEAR(got.restitution, 1.0, 2 * std::sqrt(mat.k_n / m_eff) * dt);
}

class HookeDampedImpact : public ::testing::TestWithParam<double> {};

TEST_P(HookeDampedImpact, DurationAndRestitutionMatchTheClampedOscillator) {
  const double zeta = GetParam();  // gamma / (2 w0)
  Material mat = hooke_material(1e4, 0);
  const double m_eff = 0.5 * sphere_mass(mat);
  const double w0 = std::sqrt(mat.k_n / m_eff);
  mat.gamma_n = 2 * zeta * w0;
  const Impact expected = hooke_impact(m_eff, mat.k_n, mat.gamma_n, kSpeed);
  const double dt = expected.duration / kStepsPerContact;
  const Impact got = simulate_impact(mat, kRadius, kSpeed, dt);
  const double wd = std::sqrt(w0 * w0 - 0.25 * mat.gamma_n * mat.gamma_n);
  const double textbook = std::exp(-mat.gamma_n * std::numbers::pi / (2 * wd));
  std::printf("Hooke zeta %.2f: duration %.6f of closed form, restitution %.6f (closed form %.6f, "
              "without the no-tension clamp %.6f)\n",
              zeta, got.duration / expected.duration, got.restitution, expected.restitution, textbook);
  EXPECT_NEAR(got.duration, expected.duration, 2 * dt);
  EXPECT_NEAR(got.restitution, expected.restitution, 2 * w0 * dt);
  // The clamp matters: the spheres leave faster than the unclamped oscillator would.
  EXPECT_GT(expected.restitution, textbook);
}

INSTANTIATE_TEST_SUITE_P(Damping, HookeDampedImpact, ::testing::Values(0.05, 0.2, 0.5));

TEST(HookeImpact, ClosedFormWithoutDampingIsTheUndampedLimit) {
  // A check of the helper: tiny damping tends to pi/w0 and e = 1.
  const double m = 1e-6, k = 1e4, v = 0.1;
  const Impact a = hooke_impact(m, k, 0, v), b = hooke_impact(m, k, 1e-6 * std::sqrt(k / m), v);
  EXPECT_NEAR(b.duration / a.duration, 1.0, 1e-5);
  EXPECT_NEAR(b.restitution, 1.0, 1e-5);
}
