// The narrowphase's shape-pair table (the habit of Jolt's CollisionDispatch,
// Box2D's s_registers, MuJoCo's mjCOLLISIONFUNC): one routine per ordered pair
// of shape kinds, registered in one place (dispatch.cpp). A pair registered
// only as (B, A) is served by that routine with the shapes swapped and the
// normals flipped. Normals of the results point from a to b.
#pragma once

#include "collision/posed_shape.h"

namespace grainlab {

// A pair routine: writes the pair's contacts to out[0..n) (n <= kMaxSubContacts,
// a result with touching = false is allowed: it reports the separation) and
// returns n; reads and updates the pair's warm-start cache, and, for a pair
// with a compound, the caches of its piece pairs (`pieces`: one per piece
// pair, indexed by sub-contact id, piece_cache_count of them; null: the
// pieces are collided cold).
using PairRoutine = int (*)(const PosedShape& a, const PosedShape& b, PairCache& cache, PairCache* pieces,
                            SubContact* out);

// True if a routine (direct or flipped) exists for kinds (a, b).
bool has_pair_routine(ShapeKind a, ShapeKind b);

// Collides a with b by the registered routine; throws std::logic_error for a
// pair of kinds with no routine. Returns the number of results in out.
// `pieces` as for PairRoutine (stored for a to b, like `cache`).
int collide_shapes(const PosedShape& a, const PosedShape& b, PairCache& cache, SubContact* out,
                   PairCache* pieces = nullptr);

// How many piece-pair caches a pair of these shapes keeps: pieces of a
// times pieces of b where either is a compound (a convex shape counts one),
// else 0.
int piece_cache_count(const PosedShape& a, const PosedShape& b);

}  // namespace grainlab
