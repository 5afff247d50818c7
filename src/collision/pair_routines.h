// The pair routines the shape-pair table registers (dispatch.cpp): thin
// adapters from PosedShape + PairCache to the exact routines of narrowphase.h,
// keeping their warm-start caches. One result each (sub-contact 0).
#pragma once

#include "collision/posed_shape.h"

namespace grainlab::routines {

// Grain-grain (routines_grain.cpp).
int sphere_sphere(const PosedShape& a, const PosedShape& b, PairCache& c, PairCache*, SubContact* out);
int sphere_polytope(const PosedShape& a, const PosedShape& b, PairCache& c, PairCache*, SubContact* out);
int polytope_polytope(const PosedShape& a, const PosedShape& b, PairCache& c, PairCache*, SubContact* out);

// Wall-grain (routines_wall.cpp).
int plane_sphere(const PosedShape& a, const PosedShape& b, PairCache& c, PairCache*, SubContact* out);
int plane_polytope(const PosedShape& a, const PosedShape& b, PairCache& c, PairCache*, SubContact* out);
int box_sphere(const PosedShape& a, const PosedShape& b, PairCache& c, PairCache*, SubContact* out);
int box_polytope(const PosedShape& a, const PosedShape& b, PairCache& c, PairCache*, SubContact* out);

// Compound pieces (routines_compound.cpp): a convex shape (grain or wall)
// against each piece of a compound b, and compound against compound; each
// piece pair with its own cache in `pieces` (by sub-contact id) when given.
int any_compound(const PosedShape& a, const PosedShape& b, PairCache& c, PairCache* pieces, SubContact* out);
int compound_compound(const PosedShape& a, const PosedShape& b, PairCache& c, PairCache* pieces, SubContact* out);
// Their piece-pair caches: pieces of a times pieces of b (a convex shape
// counts one).
int piece_pairs(const PosedShape& a, const PosedShape& b);

}  // namespace grainlab::routines
