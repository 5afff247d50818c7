// Contact forces as segments (definitions in force_chains.h).
#include "analysis/force_chains.h"

#include "analysis/force_stats.h"

namespace grainlab::analysis {

std::vector<ForceSegment> force_segments(const State& s) {
  const ForceStats stats = force_stats(s);
  std::vector<ForceSegment> out;
  std::size_t next_strong = 0;  // stats.strong is in pair order
  for (std::size_t p = 0; p < s.contacts.size(); ++p) {
    const Contact& pc = s.contacts[p];
    if (!in_contact(pc)) continue;
    const Vec3 n = pc.geo.normal.normalized();
    const bool strong = next_strong < stats.strong.size() && static_cast<std::size_t>(stats.strong[next_strong]) == p;
    next_strong += strong;
    out.push_back({s.bodies[pc.a].x, s.bodies[pc.b].x, pc.normal_force, (pc.force - pc.force.dot(n) * n).norm(), strong});
  }
  return out;
}

}  // namespace grainlab::analysis
