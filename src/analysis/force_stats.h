// Statistics of the normal contact forces, and the strong contacts that make
// up the force chains.
//
// Over the grain-grain contacts (in_contact(), dynamics/state.h) with normal
// force magnitudes f_c = Contact::normal_force (N):
//     mean <f> = (1/N) sum f_c,   max,   std = sqrt((1/N) sum (f_c - <f>)^2)
// (population standard deviation: these are all the contacts, not a sample).
// A contact is strong when f_c > <f> (Radjai et al. 1998: the strong network,
// carrying the deviatoric load, forms the visible force chains); the strong
// fraction is their share of the contacts. Touching pairs whose force the
// no-tension clamp set to 0 count as contacts with zero force.
#pragma once

#include "core/types.h"
#include "dynamics/state.h"

#include <cstddef>
#include <vector>

namespace grainlab::analysis {

struct ForceStats {
  std::size_t contacts = 0;       // grain-grain contacts
  double mean = 0, max = 0, std_dev = 0;  // N; all 0 with no contacts
  double strong_fraction = 0;     // share of contacts with f > mean
  std::vector<Index> strong;      // indices into State::contacts of the strong contacts, in pair order
};

ForceStats force_stats(const State& s);

}  // namespace grainlab::analysis
