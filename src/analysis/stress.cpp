// Love-Weber stress (derivation in stress.h).
#include "analysis/stress.h"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace grainlab::analysis {

StressTensor love_weber_stress(const State& s, double volume, bool include_walls) {
  if (!(volume > 0) || !std::isfinite(volume))
    throw std::invalid_argument(fmt::format("love_weber_stress: volume {} m^3 must be positive", volume));
  Mat3 sum = Mat3::Zero();
  for (const Contact& pc : s.contacts) {
    if (!in_contact(pc)) continue;
    sum += pc.force * (s.bodies[pc.b].x - s.bodies[pc.a].x).transpose();
  }
  if (include_walls) {
    for (const Contact& pc : s.wall_contacts) {
      if (!in_contact(pc)) continue;
      sum += (-pc.force) * (pc.geo.point - s.bodies[pc.b].x).transpose();
    }
  }
  StressTensor st;
  st.raw = sum / volume;
  st.sigma = 0.5 * (st.raw + st.raw.transpose());
  const double norm = st.raw.norm();
  st.asymmetry = norm > 0 ? 0.5 * (st.raw - st.raw.transpose()).norm() / norm : 0.0;
  st.mean = st.sigma.trace() / 3.0;
  const Mat3 dev = st.sigma - st.mean * Mat3::Identity();
  st.deviatoric = std::sqrt(1.5 * dev.squaredNorm());
  return st;
}

}  // namespace grainlab::analysis
