// The recipe for a contact law with a parameter of its own, followed in this
// one file: the undamped linear spring
//     f_n = k delta,   K_n = k, C_n = K_t = C_t = 0,
// with one parameter k (N/m, > 0) mixed by the mean, k = (k_a + k_b)/2. Its
// elastic energy is (1/2) f delta and its tangent stiffness f/delta.
//
// Registered at run time (register_contact_law), it is read by the real
// config code ([material.linear-spring] k = ..., or the flat [material] k),
// validated by its own rule, mixed, and its force is that of the routines the
// World runs for a law: contact_force_lanes (four at once, the World's loop),
// and the one-contact reference contact_force (contact_force_reference.h). A law the World steps is also listed in
// RegisteredLaws (dynamics/laws/registry.h: one line), which compiles its
// force loop; the World refuses this one by name.
#include "contact_force_reference.h"
#include "core/error.h"
#include "dynamics/contact_lanes.h"
#include "dynamics/laws/registry.h"
#include "head_on_impact.h"
#include "io/config.h"

#include <gtest/gtest.h>

#include <array>
#include <string>

using namespace grainlab;

namespace {

struct LinearSpringLaw {
  static constexpr const char* name = "linear-spring";
  static constexpr const char* description = "undamped linear spring";
  static constexpr std::array<LawParameter, 1> parameters{
      {{"k", "N/m", "normal stiffness", "> 0", law_rule::positive, 1e5}}};
  static constexpr int pair_slots = 1;

  static PairCoefficients mix(const Material& a, const Material& b) {
    PairCoefficients p;
    p.c[0] = 0.5 * (parameter_value(a, parameters[0]) + parameter_value(b, parameters[0]));
    return p;
  }
  template <typename T>
  static LawCoefficientsOf<T> at(const PairCoefficientsOf<T>& p, T /*delta*/, T /*r_eff*/, T /*m_eff*/) {
    return {p.c[0], T{}, T{}, T{}};
  }
  static double stiffness(const LawCoefficients& k) { return k.k_n; }
  static double tangent_stiffness(double f_n, double delta) { return f_n / delta; }
  static double elastic_energy(double f_n, double delta) { return 0.5 * f_n * delta; }
};

ContactLaw linear_spring() {
  static const ContactLaw law = register_contact_law(law_entry<LinearSpringLaw>());
  return law;
}

std::string parse_error(const std::string& text) {
  try {
    parse_config(text, "spring.toml");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

bool has(const std::string& msg, const std::string& part) { return msg.find(part) != std::string::npos; }

const char* kSpringConfig =
    "[material]\n"
    "contact_law = \"linear-spring\"\n"
    "\n"
    "[material.linear-spring]\n"
    "k = 2.5e4\n";

}  // namespace

TEST(LinearSpringLaw, TheConfigSelectsItAndReadsItsParameter) {
  const ContactLaw law = linear_spring();
  const LabSpec spec = parse_config(kSpringConfig, "spring.toml");
  EXPECT_EQ(spec.material.law, law);
  EXPECT_EQ(parameter_value(spec.material.grain, LinearSpringLaw::parameters[0]), 2.5e4);
  // The flat key reads the same; config.toml (to_toml) reads back equal.
  const LabSpec flat = parse_config("[material]\ncontact_law = \"linear-spring\"\nk = 2.5e4\n", "flat.toml");
  EXPECT_TRUE(config_differences(flat, spec).empty());
  EXPECT_TRUE(config_differences(parse_config(to_toml(spec), "back.toml"), spec).empty());
  // Left out, k is the law's default.
  EXPECT_EQ(parameter_value(LabSpec{}.material.grain, LinearSpringLaw::parameters[0]), 1e5);
}

TEST(LinearSpringLaw, ItsRuleRefusesAnImpossibleK) {
  linear_spring();
  const std::string bad =
      parse_error("[material]\ncontact_law = \"linear-spring\"\n\n[material.linear-spring]\nk = -1\n");
  EXPECT_TRUE(has(bad, "spring.toml (line 5)")) << bad;
  EXPECT_TRUE(has(bad, "material.k = -1 is impossible: it must be > 0 (N/m)")) << bad;
  const std::string unknown = parse_error("[material.linear-spring]\nkn = 1e4\n");
  EXPECT_TRUE(has(unknown, "Did you mean 'k'?")) << unknown;
  Material m;
  m.name = "rubber";
  m.more.at("k", 0) = 0;
  try {
    validate(m, linear_spring());
    FAIL() << "k = 0 accepted";
  } catch (const InputError& e) {
    EXPECT_TRUE(has(e.what(), "material 'rubber': k = 0 is impossible; it must be > 0 (N/m)")) << e.what();
  }
}

TEST(LinearSpringLaw, TwoSpheresPushWithKTimesTheOverlap) {
  const ContactLaw law = linear_spring();
  const Material grain = parse_config(kSpringConfig, "spring.toml").material.grain;
  const PairCoefficients pair = mix(grain, grain, law);
  // Spheres of radius r at x = 0 and x = 2r - delta, closing at 0.3 m/s with
  // some sliding: an undamped spring without tangential stiffness pushes b
  // along +x with k delta, whatever the velocity.
  const double r = 1e-3, delta = 2e-6, dt = 1e-7;
  ContactKinematics c{Vec3::UnitX(), delta, Vec3(-0.3, 0.1, 0), 4e-6, 0.5 * r};
  Vec3 xi = Vec3::Zero();
  const Vec3 f = contact_force<LinearSpringLaw>(pair, c, dt, xi);
  EXPECT_EQ(f, Vec3(2.5e4 * delta, 0, 0));

  ContactLanes lanes{};
  PairCoefficientsOf<Lanes> p{};
  for (int l = 0; l < kLanes; ++l) {
    lanes.nx[l] = 1, lanes.delta[l] = (l + 1) * delta, lanes.vx[l] = -0.3, lanes.vy[l] = 0.1;
    lanes.m_eff[l] = c.m_eff, lanes.r_eff[l] = c.r_eff, lanes.gain[l] = 1, lanes.share[l] = 1;
    p.c[0][l] = pair.c[0], p.friction[l] = pair.friction;
  }
  const ForceLanes four = contact_force_lanes<LinearSpringLaw>(p, lanes, dt);
  for (int l = 0; l < kLanes; ++l) {
    EXPECT_EQ(four.fx[l], 2.5e4 * lanes.delta[l]) << l;
    EXPECT_EQ(four.fy[l], 0) << l;
    EXPECT_EQ(four.f_n[l], 2.5e4 * lanes.delta[l]) << l;
  }
  // Not in RegisteredLaws: the World has no force loop for it and says so.
  try {
    testing_support::head_on_impact(law, grain, r, 0.3, dt);
    FAIL() << "the World stepped a law without a compiled force loop";
  } catch (const InputError& e) {
    EXPECT_TRUE(has(e.what(), "'linear-spring' has no compiled force loop")) << e.what();
  }
}
