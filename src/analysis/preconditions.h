// Argument checks shared by the analysis functions. A mismatch here is a
// caller's mistake, not a user's input, so it throws std::invalid_argument.
#pragma once

#include "analysis/grain_mask.h"
#include "dynamics/state.h"

#include <fmt/format.h>

#include <cstddef>
#include <stdexcept>

namespace grainlab::analysis {

// `mask` is null or has one flag per body. `who` names the measurement.
inline void check_mask(const GrainMask* mask, std::size_t body_count, const char* who) {
  if (mask && mask->size() != body_count)
    throw std::invalid_argument(
        fmt::format("{}: the grain mask has {} flags for {} bodies", who, mask->size(), body_count));
}

// `now` and `ref` hold the same bodies (a current and a reference State).
inline void check_same_bodies(const State& now, const State& ref, const char* who) {
  if (now.bodies.size() != ref.bodies.size())
    throw std::invalid_argument(fmt::format(
        "{}: the current State has {} bodies, the reference {}; they must be the same grains", who,
        now.bodies.size(), ref.bodies.size()));
}

}  // namespace grainlab::analysis
