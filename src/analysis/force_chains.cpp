// Contact forces as segments (definitions in force_chains.h).
#include "analysis/force_chains.h"

namespace grainlab::analysis {

std::vector<ForceSegment> force_segments(const State& s) {
  std::vector<ForceSegment> out;
  for (const PairContact& pc : s.pairs) {
    if (!in_contact(pc)) continue;
    const Vec3 n = pc.geo.normal.normalized();
    out.push_back({s.bodies[pc.a].x, s.bodies[pc.b].x, pc.normal_force, (pc.force - pc.force.dot(n) * n).norm()});
  }
  return out;
}

}  // namespace grainlab::analysis
