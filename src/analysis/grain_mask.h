// A subset of the grains (the shear band, a layer, a region): one flag per
// body index, 1 = in the subset. Masks are what the analysis functions take
// wherever a measurement can be restricted to some grains.
#pragma once

#include "core/types.h"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace grainlab::analysis {

using GrainMask = std::vector<std::uint8_t>;

// The mask of `grains` (body indices) among `body_count` bodies.
inline GrainMask mask_of(std::size_t body_count, std::span<const Index> grains) {
  GrainMask m(body_count, 0);
  for (Index i : grains) m.at(static_cast<std::size_t>(i)) = 1;
  return m;
}

// Number of grains in the mask.
inline std::size_t mask_count(const GrainMask& m) {
  std::size_t n = 0;
  for (std::uint8_t f : m) n += f != 0;
  return n;
}

}  // namespace grainlab::analysis
