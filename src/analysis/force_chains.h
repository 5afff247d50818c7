// The grain-grain contact forces as segments between grain centres (paper
// Fig. 17): per touching pair (in_contact(), dynamics/state.h) the two
// centres, the normal force magnitude Contact::normal_force (N; the
// measure force_stats.h splits strong and weak chains by), and the magnitude
// of the tangential part of the contact force, |F - (F.n) n| with n the unit
// contact normal (N), and whether it is strong (normal force above the mean,
// force_stats.h).
#pragma once

#include "core/types.h"
#include "dynamics/state.h"

#include <vector>

namespace grainlab::analysis {

struct ForceSegment {
  Vec3 a = Vec3::Zero(), b = Vec3::Zero();  // centres of the two grains (m)
  double normal_force = 0;                  // N
  double tangential_force = 0;              // N
  bool strong = false;                      // part of the strong network (force_stats.h)
};

// One segment per grain-grain contact, in State::pairs order.
std::vector<ForceSegment> force_segments(const State& s);

}  // namespace grainlab::analysis
