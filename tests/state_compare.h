// Bitwise comparison of two States (field by field: structs have padding that
// memcmp must not see), for determinism and restart tests.
#pragma once

#include "dynamics/state.h"

#include <cstring>

namespace grainlab::testing_support {

// True if bodies, walls and the tangential springs of the pairs are identical bit for bit.
inline bool same_state_bits(const State& a, const State& b) {
  const auto eq = [](const auto& x, const auto& y) { return std::memcmp(x.data(), y.data(), sizeof(x)) == 0; };
  if (a.step != b.step || a.bodies.size() != b.bodies.size() || a.walls.size() != b.walls.size() ||
      a.pairs.size() != b.pairs.size())
    return false;
  for (std::size_t i = 0; i < a.bodies.size(); ++i) {
    const BodyState &p = a.bodies[i], &q = b.bodies[i];
    if (!eq(p.x, q.x) || !eq(p.v, q.v) || !eq(p.w, q.w) || !eq(p.q.coeffs(), q.q.coeffs())) return false;
  }
  for (std::size_t k = 0; k < a.walls.size(); ++k)
    if (!eq(a.walls[k].x, b.walls[k].x) || !eq(a.walls[k].v, b.walls[k].v)) return false;
  for (std::size_t k = 0; k < a.pairs.size(); ++k)
    if (a.pairs[k].key() != b.pairs[k].key() || !eq(a.pairs[k].xi, b.pairs[k].xi)) return false;
  return true;
}

}  // namespace grainlab::testing_support
