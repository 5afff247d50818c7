// The changing part of a simulation (MuJoCo's mjData): poses, velocities,
// wall motion, the broadphase's candidate pairs with their warm-start caches,
// and the contacts with their tangential springs (the contact history). Saving a State (with its Model) is a
// full checkpoint; restoring it reproduces the run bit for bit.
#pragma once

#include "collision/contact_result.h"
#include "collision/posed_shape.h"
#include "core/types.h"

#include <cstdint>
#include <vector>

namespace grainlab {

// Hot per-body state, packed.
struct BodyState {
  Vec3 x = Vec3::Zero();  // centre of mass (m)
  Vec3 v = Vec3::Zero();  // velocity (m/s)
  Vec3 w = Vec3::Zero();  // angular velocity, world frame (rad/s)
  Quat q = Quat::Identity();  // orientation: local (principal) frame to world
};

struct WallState {
  Vec3 x = Vec3::Zero();  // plane: a point on it; box: its centre (m)
  Quat q = Quat::Identity();  // plane: local +z is the outward normal
  Vec3 v = Vec3::Zero();      // prescribed translational velocity (m/s)
  Vec3 force = Vec3::Zero();  // force the grains put on the wall in the last step (N)
};

// A candidate pair from the broadphase: a grain with a grain (a < b) or a
// wall with a grain (a = wall), and its narrowphase warm-start cache. It
// lives while the broadphase keeps the pair.
struct CandidatePair {
  Index a = 0, b = 0;
  PairCache cache;  // GJK direction (initially b's centre minus a's), support hints, warm flag
  // Where the pair's contacts begin in the contact list of the last
  // narrowphase: kNoContacts if it had none, kUnknownContacts if not known (a
  // new or restored pair). A hint for carrying springs, checked before use,
  // so it never changes a result; not checkpointed.
  std::int32_t first_contact = kUnknownContacts;
  static constexpr std::int32_t kNoContacts = -1, kUnknownContacts = -2;
  // A pair with a compound: where its piece-pair caches begin in the State's
  // piece_caches (or wall_piece_caches), piece_cache_count of them
  // (collision/dispatch.h); -1: none (convex shapes, or not yet given: cold).
  std::int32_t pieces = -1;
  // True when every piece-pair cache of the pair is known to be cold (set
  // when the pair's bounding spheres are apart and its caches were made cold,
  // cleared when its pieces are collided): a hint that spares making them
  // cold again at every step the pair stays apart, so it never changes a
  // result; not checkpointed (a restored pair makes them cold once more).
  bool pieces_cold = false;

  std::uint64_t key() const {
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) |
           static_cast<std::uint32_t>(b);
  }
};

// A contact: bodies a and b (as in CandidatePair) touching at sub-contact
// `sub` of their pair (0 for convex shapes; compound shapes touch at several
// places at once). Its tangential spring is carried from step to step while
// the same (a, b, sub) keeps touching.
struct Contact {
  Index a = 0, b = 0;
  std::int32_t sub = 0;
  Vec3 xi = Vec3::Zero();     // tangential spring (m)
  ContactResult geo;          // geometry of the current step
  Vec3 force = Vec3::Zero();  // force on b at geo.point (N); on a it is -force
  Vec3 torque = Vec3::Zero(); // extra torque on b (patch damping, N m); on a it is -torque
  double normal_force = 0;    // N

  // Orders contacts by (a, b, sub): State's contact lists are sorted by it.
  bool operator<(const Contact& o) const {
    return a != o.a ? a < o.a : b != o.b ? b < o.b : sub < o.sub;
  }
  bool same_key(const Contact& o) const { return a == o.a && b == o.b && sub == o.sub; }
};

// True if the contact touches in the current step and so carries a force: the
// one criterion for "in contact" (World::contact_count, coordination numbers,
// contact output). The World keeps only touching contacts, so a contact read
// from a State is touching; the test stays for hand-built States.
inline bool in_contact(const Contact& c) { return c.geo.touching; }

// Calls f(a, b) once for every body pair with at least one touching contact
// in `contacts` (sorted by (a, b, sub)), in order: touching PAIRS, not
// sub-contacts (coordination numbers count pairs, paper Eq. 22).
template <typename F>
void for_each_touching_pair(const std::vector<Contact>& contacts, F&& f) {
  bool have = false;
  Index last_a = 0, last_b = 0;
  for (const Contact& c : contacts) {
    if (!in_contact(c) || (have && c.a == last_a && c.b == last_b)) continue;
    have = true;
    last_a = c.a, last_b = c.b;
    f(c.a, c.b);
  }
}

// Number of body pairs with at least one touching contact in `contacts`.
inline std::size_t touching_pair_count(const std::vector<Contact>& contacts) {
  std::size_t n = 0;
  for_each_touching_pair(contacts, [&n](Index, Index) { ++n; });
  return n;
}

struct State {
  double time = 0;        // s
  std::int64_t step = 0;
  std::vector<BodyState> bodies;
  std::vector<WallState> walls;
  std::vector<CandidatePair> pairs;       // grain-grain candidates, sorted by (a, b)
  std::vector<CandidatePair> wall_pairs;  // wall-grain candidates, sorted by (wall, grain)
  // The piece-pair caches of the candidates with a compound (concave grains):
  // the blocks CandidatePair::pieces points at, in the pairs' order.
  std::vector<PairCache> piece_caches, wall_piece_caches;
  std::vector<Contact> contacts;          // touching grain-grain contacts, sorted by (a, b, sub)
  std::vector<Contact> wall_contacts;     // touching wall-grain contacts, sorted by (wall, grain, sub)
  // Verlet-skin bookkeeping: positions at the last broadphase rebuild. Code
  // that moves grains by hand (not by stepping) sets rebuild_pairs.
  std::vector<Vec3> x_at_rebuild;
  bool rebuild_pairs = true;
  // A world of spheres keeps its wall-grain candidates while no wall has
  // moved by half the skin (World::broadphase): the wall poses they were
  // found at (checkpointed since format version 7); empty means find them
  // again.
  std::vector<Vec3> wall_x_at_rebuild;
  std::vector<Quat> wall_q_at_rebuild;
};

}  // namespace grainlab
