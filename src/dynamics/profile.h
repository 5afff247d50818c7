// Time spent in each phase of World::step, summed over steps (seconds).
#pragma once

#include <array>
#include <cstdint>
#include <string_view>

namespace grainlab {

enum class Phase { Bounds, Broadphase, Narrowphase, Forces, Controllers, Integrate, Bookkeeping, Count };

inline constexpr std::array<std::string_view, static_cast<int>(Phase::Count)> kPhaseNames = {
    "bounds", "broadphase", "narrowphase", "forces", "controllers", "integrate", "bookkeeping"};

struct StepProfile {
  std::array<double, static_cast<int>(Phase::Count)> seconds{};
  std::int64_t steps = 0;
  std::int64_t broadphase_rebuilds = 0;
  std::int64_t pair_tests = 0;      // narrowphase calls
  std::int64_t contacts = 0;        // touching pairs, summed over steps

  double& operator[](Phase p) { return seconds[static_cast<int>(p)]; }
  double operator[](Phase p) const { return seconds[static_cast<int>(p)]; }
};

}  // namespace grainlab
