// Restitution calibration of the Hertz-material law and material validation.
#include "dynamics/laws/registry.h"
#include "core/error.h"
#include "dynamics/material.h"

#include <gtest/gtest.h>

using namespace grainlab;

TEST(Material, ElasticHasNoDamping) {
  EXPECT_EQ(restitution_to_beta(1.0), 0.0);
  EXPECT_NEAR(hertz_restitution(0.0), 1.0, 1e-6);
}

TEST(Material, BetaInvertsRestitution) {
  double last_beta = 0;
  for (double e : {0.9, 0.7, 0.5, 0.3, 0.1}) {
    const double beta = restitution_to_beta(e);
    EXPECT_GT(beta, last_beta) << "lower restitution needs more damping";
    EXPECT_NEAR(hertz_restitution(beta), e, 1e-6);
    last_beta = beta;
  }
}

TEST(Material, LinearSpringFormulaIsNotGoodEnoughForHertz) {
  // The textbook beta = -ln e / sqrt(ln^2 e + pi^2) misses e for Hertz by more
  // than the 1 % the engine promises: this is why grainlab calibrates.
  const double e = 0.5;
  const double textbook = -std::log(e) / std::sqrt(std::log(e) * std::log(e) + M_PI * M_PI);
  EXPECT_GT(std::abs(hertz_restitution(textbook) - e) / e, 0.01);
}

TEST(Material, ImpossibleValuesAreRefusedByName) {
  Material m;
  m.name = "quartz";
  m.density = -1;
  try {
    validate(m, contact_law<HertzMaterialLaw>());
    FAIL() << "negative density accepted";
  } catch (const InputError& err) {
    EXPECT_NE(std::string(err.what()).find("quartz"), std::string::npos);
    EXPECT_NE(std::string(err.what()).find("density"), std::string::npos);
  }
  m.density = 2650;
  m.restitution = 1.5;
  EXPECT_THROW(validate(m, contact_law<HertzMaterialLaw>()), InputError);
  EXPECT_THROW(parse_contact_law("hertzian"), InputError);
}
