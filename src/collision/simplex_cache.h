// The last GJK simplex of a pair of polytopes, kept between steps as the
// vertex indices it was made of (as Box2D's b2SimplexCache): the next GJK of
// the pair starts from those points at the new poses instead of from a single
// support point.
//
// Why it is safe: GJK converges to the closest point of C = A - B to the
// origin from any starting simplex of points of C, and A[i] - B[j] is a point
// of C for every pair of vertex indices, whatever the motion since. Why it is
// fast: between two steps the closest feature of a DEM contact rarely
// changes, so the restored triangle already holds the closest point and one
// support query confirms it (about 12 GJK iterations fall to 1 or 2 on the
// settled 2000-face bed; bench/bench_scenes).
#pragma once

#include "core/types.h"

#include <cstdint>

namespace grainlab {

struct SimplexCache {
  std::int32_t n = 0;  // points kept (0: none, start cold)
  Index a[3] = {0, 0, 0}, b[3] = {0, 0, 0};

  // The same points for the pair taken the other way round (B, A).
  SimplexCache swapped() const {
    SimplexCache s;
    s.n = n;
    for (int i = 0; i < 3; ++i) s.a[i] = b[i], s.b[i] = a[i];
    return s;
  }
};

}  // namespace grainlab
