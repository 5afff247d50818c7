// The per-sample micromechanics of a shear test (definitions in shear_sample.h).
#include "analysis/shear_sample.h"

#include "analysis/coordination.h"
#include "analysis/fabric.h"
#include "analysis/rotation.h"

#include <limits>
#include <numbers>
#include <vector>

namespace grainlab::analysis {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kDeg = 180.0 / std::numbers::pi;

// Psi of the contact normals (of the grains in mask, if given); NaN without contacts.
double fabric_psi(const State& s, const GrainMask* mask) {
  const std::vector<Vec3> normals = contact_normals(s, mask);
  if (normals.empty()) return kNaN;
  return octahedral_fabric_factor(fabric_tensors(normals).phi);
}

}  // namespace

ShearSample shear_sample(const State& now, const State& ref, const BandInputs& in) {
  if (ref.bodies.size() != now.bodies.size())  // not shearing yet: nothing to measure from
    return {kNaN, kNaN, kNaN, kNaN, kNaN, kNaN, kNaN};
  const BandResult b = band_result(now, ref, in);
  const bool band = b.band.found && mask_count(b.mask) > 0;
  const GrainMask* mask = band ? &b.mask : nullptr;
  return {
      mean_rotation_angle(now, ref) * kDeg,
      band ? mean_rotation_angle(now, ref, mask) * kDeg : kNaN,
      band ? coordination_number(now, mask) : kNaN,
      fabric_psi(now, nullptr),
      band ? fabric_psi(now, mask) : kNaN,
      b.band.found ? b.band.z_low : kNaN,
      b.band.found ? b.band.z_high : kNaN,
  };
}

}  // namespace grainlab::analysis
