// Bitwise comparison of two States (field by field: structs have padding that
// memcmp must not see), for determinism and restart tests.
#pragma once

#include "dynamics/state.h"

#include <cstring>

namespace grainlab::testing_support {

// True if bodies, walls, the candidate pairs with their warm-start caches
// (and their piece pairs'), and the contacts with their tangential springs
// are identical bit for bit.
inline bool same_state_bits(const State& a, const State& b) {
  const auto eq = [](const auto& x, const auto& y) { return std::memcmp(x.data(), y.data(), sizeof(x)) == 0; };
  if (a.step != b.step || a.bodies.size() != b.bodies.size() || a.walls.size() != b.walls.size() ||
      a.pairs.size() != b.pairs.size() || a.wall_pairs.size() != b.wall_pairs.size() ||
      a.contacts.size() != b.contacts.size() || a.wall_contacts.size() != b.wall_contacts.size())
    return false;
  for (std::size_t i = 0; i < a.bodies.size(); ++i) {
    const BodyState &p = a.bodies[i], &q = b.bodies[i];
    if (!eq(p.x, q.x) || !eq(p.v, q.v) || !eq(p.w, q.w) || !eq(p.q.coeffs(), q.q.coeffs())) return false;
  }
  for (std::size_t k = 0; k < a.walls.size(); ++k)
    if (!eq(a.walls[k].x, b.walls[k].x) || !eq(a.walls[k].v, b.walls[k].v)) return false;
  const auto same_cache = [&](const PairCache& p, const PairCache& q) {
    return eq(p.dir, q.dir) && p.hint_a == q.hint_a && p.hint_b == q.hint_b && p.warm == q.warm &&
           p.simplex.n == q.simplex.n && std::memcmp(p.simplex.a, q.simplex.a, sizeof(p.simplex.a)) == 0 &&
           std::memcmp(p.simplex.b, q.simplex.b, sizeof(p.simplex.b)) == 0;
  };
  for (const auto* list : {&a.pairs, &a.wall_pairs}) {
    const auto& other = list == &a.pairs ? b.pairs : b.wall_pairs;
    for (std::size_t k = 0; k < list->size(); ++k)
      if ((*list)[k].key() != other[k].key() || (*list)[k].pieces != other[k].pieces ||
          !same_cache((*list)[k].cache, other[k].cache))
        return false;
  }
  for (const auto* pool : {&a.piece_caches, &a.wall_piece_caches}) {
    const auto& other = pool == &a.piece_caches ? b.piece_caches : b.wall_piece_caches;
    if (pool->size() != other.size()) return false;
    for (std::size_t k = 0; k < pool->size(); ++k)
      if (!same_cache((*pool)[k], other[k])) return false;
  }
  for (const auto* list : {&a.contacts, &a.wall_contacts}) {
    const auto& other = list == &a.contacts ? b.contacts : b.wall_contacts;
    for (std::size_t k = 0; k < list->size(); ++k)
      if (!(*list)[k].same_key(other[k]) || !eq((*list)[k].xi, other[k].xi)) return false;
  }
  return true;
}

}  // namespace grainlab::testing_support
