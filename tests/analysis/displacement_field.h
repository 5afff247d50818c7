// Shared by the shear-band tests: a synthetic displacement field is a
// specimen's grains at the reference and now, laid out in millimetres.
#pragma once

#include "dynamics/state.h"

namespace grainlab::analysis_test {

inline constexpr double kMm = 1e-3;  // m

struct Field {
  State ref, now;  // the grains at the reference and now
};

}  // namespace grainlab::analysis_test
