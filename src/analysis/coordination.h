// Coordination number (paper Eq. 22) and per-grain contact counts.
//
// A contact here is a grain-grain PAIR touching at one place or more: it has
// at least one in_contact() sub-contact (dynamics/state.h, the one criterion;
// for_each_touching_pair counts each pair once). Let c_i be the number of contacts of
// grain i. Each contact has two grains, so sum_i c_i = 2 N_c and
//     CN = 2 N_c / N_p = (1/N_p) sum_i c_i,
// the mean number of contacts per grain. Over a subset S of the grains (the
// shear band, say) grainlab uses the same per-grain mean,
//     CN_S = (1/|S|) sum_{i in S} c_i,
// so a contact between two grains of S counts twice (once for each), a
// contact between a grain of S and one outside once; S = all grains gives
// Eq. 22 back. Wall contacts are left out, as is usual in DEM (a wall is not a
// grain and has no coordination of its own); `include_walls` adds them to c_i
// for output that wants every support a grain has.
#pragma once

#include "analysis/grain_mask.h"
#include "core/types.h"
#include "dynamics/state.h"

#include <vector>

namespace grainlab::analysis {

// Number of touching pairs of each body (one entry per body). Grain-grain
// only, unless include_walls.
std::vector<Index> contact_counts(const State& s, bool include_walls = false);

// CN = 2 N_c / N_p over all grains, or CN_S over the grains in `mask` (see
// above); grain-grain contacts only. 0 for an empty set.
double coordination_number(const State& s, const GrainMask* mask = nullptr);

}  // namespace grainlab::analysis
