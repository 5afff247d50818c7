// The narrowphase's shape-pair table (the habit of Jolt's CollisionDispatch,
// Box2D's s_registers, MuJoCo's mjCOLLISIONFUNC): one routine per ordered pair
// of shape kinds, registered in one place (dispatch.cpp) with what the pair
// needs from the caller that keeps it (PairNeeds: its slots, its caches,
// whether it takes the compact path), so that the caller (dynamics/
// collision_driver.h) asks the table and never names a kind. A pair
// registered only as (B, A) is served by that routine with the shapes
// swapped and the normals flipped. Normals of the results point from a to b.
// A program may add a kind and its routines at run time
// (register_shape_kind, register_pair_routine), before it steps a World.
#pragma once

#include "collision/narrowphase.h"
#include "collision/posed_shape.h"
#include "collision/sphere_pairs.h"

#include <cstddef>
#include <string>

namespace grainlab {

// A pair routine: writes the pair's contacts to out[0..n) (n <= kMaxSubContacts,
// a result with touching = false is allowed: it reports the separation) and
// returns n; reads and updates the pair's warm-start cache, and, for a pair
// with a compound, the caches of its piece pairs (`pieces`: one per piece
// pair, indexed by sub-contact id, piece_cache_count of them; null: the
// pieces are collided cold).
using PairRoutine = int (*)(const PosedShape& a, const PosedShape& b, PairCache& cache, PairCache* pieces,
                            SubContact* out);

// How many extra warm-start caches a pair of these posed shapes keeps
// besides its PairCache (a compound's: one per piece pair).
using ExtraCacheCount = int (*)(const PosedShape& a, const PosedShape& b);

// What a pair of kinds needs from the caller that keeps it, declared with its
// routine in the table.
struct PairNeeds {
  // Most sub-contacts its routine writes (1 to kMaxSubContacts): the slots
  // the caller gives each pair.
  int sub_contacts = 1;
  // Its routine reads or updates the PairCache. A pair whose routine does
  // not keeps the default cache, so its caller may keep such pairs in a
  // candidate list found earlier (the wall pairs of spheres) with the bits
  // of a list found anew.
  bool reads_cache = true;
  // How many extra caches a pair keeps (`pieces` of PairRoutine), the
  // caller storing them from step to step; null: none.
  ExtraCacheCount extra_caches = nullptr;
  // Both shapes are a centre and a radius (CompactPose): collide_compact
  // below gives the pair's one result (sub 0) from 32 bytes a shape, without
  // posing shapes or calling through the table (the 2000-bead lab's path).
  bool compact = false;
};

// What the pair of kinds (a, b) needs; all false / null where no routine is
// registered.
const PairNeeds& pair_needs(ShapeKind a, ShapeKind b);

// A new shape kind, for a program that brings its own (tests/dynamics/
// ellipsoid_kind_test.cpp): the next free id, up to kMaxShapeKinds (else
// std::length_error). `name` is used in messages.
ShapeKind register_shape_kind(const std::string& name);
// Registers `fn` for the pair of kinds (a, b) with its needs; it then also
// serves (b, a), flipped, unless (b, a) has a routine of its own. Call before
// any World steps: the table is read without a lock.
void register_pair_routine(ShapeKind a, ShapeKind b, PairRoutine fn, PairNeeds needs);
// Kinds known so far: the built-in ones, then the registered ones.
int shape_kind_count();
// The name of a kind ("sphere", ...).
std::string shape_kind_name(ShapeKind k);

// A shape of a compact pair: its centre and its radius (PosedShape::pos and
// ::radius), side by side.
struct CompactPose {
  Vec3 x;
  double radius;
};
static_assert(sizeof(CompactPose) == 4 * sizeof(double) && offsetof(CompactPose, radius) == 3 * sizeof(double),
              "a CompactPose is read as x, y, z, radius (sphere_pairs.h)");

// The routine of a compact pair (PairNeeds::compact): the same bits as the
// table's routine for the pair (collide(), sphere_pairs.h).
inline ContactResult collide_compact(const CompactPose& a, const CompactPose& b) {
  const SphereXYZR pa[4] = {a.x.data(), a.x.data(), a.x.data(), a.x.data()};
  const SphereXYZR pb[4] = {b.x.data(), b.x.data(), b.x.data(), b.x.data()};
  SpherePairsOut out;
  sphere_pairs(pa, pb, out);
  return sphere_pair_result(out, 0);
}

// True if a routine (direct or flipped) exists for kinds (a, b).
bool has_pair_routine(ShapeKind a, ShapeKind b);

// Collides a with b by the registered routine; throws std::logic_error for a
// pair of kinds with no routine. Returns the number of results in out.
// `pieces` as for PairRoutine (stored for a to b, like `cache`).
int collide_shapes(const PosedShape& a, const PosedShape& b, PairCache& cache, SubContact* out,
                   PairCache* pieces = nullptr);

// How many extra caches a pair of these shapes keeps (its PairNeeds'
// extra_caches; 0 where it has none): a pair with a compound keeps one per
// piece pair.
int piece_cache_count(const PosedShape& a, const PosedShape& b);

}  // namespace grainlab
