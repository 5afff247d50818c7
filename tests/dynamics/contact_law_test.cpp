// Every registered contact law, checked the same way (a new law gets these
// tests by registering):
//  * its tangent stiffness d f_n / d delta, both from the coefficients
//    (stiffness) and from a force and an overlap (tangent_stiffness), against a
//    central finite difference of the elastic force f(delta) = K_n(delta) delta:
//    (f(d + h) - f(d - h)) / 2h = f'(d) + f'''(d) h^2 / 6 + ..., so with
//    h = 1e-4 d the truncation is about 1e-9 relative for these power laws;
//  * its elastic energy against int_0^delta f(x) dx by composite Simpson on
//    20000 intervals (for f ~ x^{3/2} the error near 0 falls as h^{5/2}:
//    below 1e-9 relative);
//  * its name parses back to it, and the default material passes its validation.
#include "core/error.h"
#include "dynamics/laws/registry.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using namespace grainlab;

namespace {

class EveryLaw : public ::testing::TestWithParam<std::size_t> {
 protected:
  ContactLaw law = ContactLaw::at_index(GetParam());
  PairCoefficients pair = mix(Material{}, Material{}, law);
  double r_eff = 0.25e-3, m_eff = 1e-6;  // m, kg

  // The elastic normal force at overlap delta (no damping: v_n = 0).
  double force(double delta) const { return law->at(pair, delta, r_eff, m_eff).k_n * delta; }
};

std::string law_name(const ::testing::TestParamInfo<std::size_t>& info) {
  std::string s = contact_law_name(ContactLaw::at_index(info.param));
  for (char& c : s)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return s;
}

}  // namespace

TEST_P(EveryLaw, TangentStiffnessIsTheDerivativeOfTheForce) {
  for (double fraction : {1e-4, 1e-3, 1e-2}) {
    const double delta = fraction * r_eff, h = 1e-4 * delta;
    const double slope = (force(delta + h) - force(delta - h)) / (2 * h);
    const double f = force(delta);
    EXPECT_NEAR(law->tangent_stiffness(f, delta) / slope, 1.0, 1e-6) << "overlap " << delta;
    EXPECT_NEAR(law->stiffness(law->at(pair, delta, r_eff, m_eff)) / slope, 1.0, 1e-6) << "overlap " << delta;
  }
}

TEST_P(EveryLaw, ElasticEnergyIsTheWorkOfTheForce) {
  for (double fraction : {1e-4, 1e-2}) {
    const double delta = fraction * r_eff;
    const int n = 20000;  // even
    const double h = delta / n;
    double sum = force(0) + force(delta);
    for (int i = 1; i < n; ++i) sum += (i % 2 ? 4 : 2) * force(i * h);
    const double work = sum * h / 3;
    EXPECT_NEAR(law->elastic_energy(force(delta), delta) / work, 1.0, 1e-8) << "overlap " << delta;
  }
}

TEST_P(EveryLaw, NameParsesBackAndDefaultMaterialIsValid) {
  EXPECT_EQ(parse_contact_law(contact_law_name(law)), law);
  EXPECT_NO_THROW(validate(Material{}, law));
  Material slippery;
  slippery.friction = 0.1;
  EXPECT_EQ(mix(Material{}, slippery, law).friction, 0.1) << "the slipperier surface governs";
  Material bad;
  bad.name = "quartz";
  bad.density = -1;
  EXPECT_THROW(validate(bad, law), InputError);
}

INSTANTIATE_TEST_SUITE_P(Registered, EveryLaw, ::testing::Range<std::size_t>(0, RegisteredLaws::size), law_name);

TEST(ContactLawRegistry, UnknownNameListsEveryRegisteredLaw) {
  try {
    parse_contact_law("mindlin");
    FAIL() << "an unknown law was accepted";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    for (std::size_t i = 0; i < RegisteredLaws::size; ++i) {
      const std::string name = std::string("\"") + contact_law_name(ContactLaw::at_index(i)) + "\"";
      EXPECT_NE(msg.find(name), std::string::npos) << msg;
    }
  }
}

TEST(ContactLawRegistry, HandlesOfTypesAndNamesAgree) {
  EXPECT_EQ(contact_law<HookeLaw>(), parse_contact_law("hooke"));
  EXPECT_EQ(contact_law<HertzUserLaw>(), parse_contact_law("hertz"));
  EXPECT_EQ(contact_law<HertzMaterialLaw>(), parse_contact_law("hertz-material"));
  EXPECT_EQ(ContactLaw(), contact_law<DefaultLaw>());
  EXPECT_THROW(ContactLaw::at_index(RegisteredLaws::size), InputError);
}

// The Hertz-material coefficients written out from two unlike materials, as
// hertz_material.h derives them: E*, G*, s = sqrt(R* delta), S_n = 2 E* s,
// S_t = 8 G* s, K_n = (4/3) E* s, K_t = S_t, C_n = 2 sqrt(5/6) beta
// sqrt(S_n m*), C_t = 2 sqrt(5/6) beta sqrt(S_t m*) (the law computes C_t from
// C_n's square root; this checks that shortcut against the formula).
TEST(HertzMaterialLaw, CoefficientsAreHertzMindlinsFromTheMaterialConstants) {
  Material a, b;
  a.youngs_modulus = 70e9, a.poisson_ratio = 0.22, a.restitution = 0.6;
  b.youngs_modulus = 4e9, b.poisson_ratio = 0.35, b.restitution = 0.4;
  const double e_star = 1 / ((1 - 0.22 * 0.22) / 70e9 + (1 - 0.35 * 0.35) / 4e9);
  const double g_star = 1 / (2 * (2 - 0.22) * (1 + 0.22) / 70e9 + 2 * (2 - 0.35) * (1 + 0.35) / 4e9);
  const double beta = restitution_to_beta(0.5);
  const PairCoefficients p = HertzMaterialLaw::mix(a, b);
  const double r_eff = 0.3e-3, m_eff = 2e-7, delta = 1e-6;
  const double s = std::sqrt(r_eff * delta), s_n = 2 * e_star * s, s_t = 8 * g_star * s;
  const LawCoefficients k = HertzMaterialLaw::at(p, delta, r_eff, m_eff);
  EXPECT_NEAR(k.k_n / (4.0 / 3.0 * e_star * s), 1, 1e-14);
  EXPECT_NEAR(k.k_t / s_t, 1, 1e-14);
  EXPECT_NEAR(k.c_n / (2 * std::sqrt(5.0 / 6.0) * beta * std::sqrt(s_n * m_eff)), 1, 1e-14);
  EXPECT_NEAR(k.c_t / (2 * std::sqrt(5.0 / 6.0) * beta * std::sqrt(s_t * m_eff)), 1, 1e-14);
}
