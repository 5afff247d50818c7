// Coordination number (definitions in coordination.h).
#include "analysis/coordination.h"

#include "analysis/preconditions.h"

namespace grainlab::analysis {

std::vector<Index> contact_counts(const State& s, bool include_walls) {
  std::vector<Index> c(s.bodies.size(), 0);
  for_each_touching_pair(s.contacts, [&c](Index a, Index b) {
    ++c[a];
    ++c[b];
  });
  if (include_walls) for_each_touching_pair(s.wall_contacts, [&c](Index, Index b) { ++c[b]; });
  return c;
}

double coordination_number(const State& s, const GrainMask* mask) {
  check_mask(mask, s.bodies.size(), "coordination_number");
  const std::vector<Index> c = contact_counts(s);
  std::size_t contacts = 0, grains = 0;
  for (std::size_t i = 0; i < c.size(); ++i) {
    if (mask && !(*mask)[i]) continue;
    contacts += static_cast<std::size_t>(c[i]);
    ++grains;
  }
  return grains ? static_cast<double>(contacts) / static_cast<double>(grains) : 0.0;
}

}  // namespace grainlab::analysis
