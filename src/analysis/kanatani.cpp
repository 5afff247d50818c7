// Kanatani's density (derivation in kanatani.h).
#include "analysis/kanatani.h"

#include <numbers>

namespace grainlab::analysis {

double KanataniDensity::operator()(const Vec3& n) const {
  return (1.0 + n.dot(D2 * n) + D4.contract(n)) / (4.0 * std::numbers::pi);
}

KanataniDensity kanatani_density(const FabricTensors& fabric, bool fourth_order) {
  KanataniDensity f;
  f.D2 = 7.5 * deviatoric_part(fabric.phi);
  if (fourth_order) f.D4 = (315.0 / 8.0) * deviatoric_part(fabric.phi4);
  return f;
}

}  // namespace grainlab::analysis
