// Peaks of a recorded curve, and the rule that says whether a largest value
// is a peak at all.
//
// A curve y_k is recorded against the test's progress e_k (shear strain,
// axial strain), k = 0 .. n-1; NaN samples (a value not yet defined) are
// skipped. Its largest value is y_m = max_k y_k (the first such k), at e_m.
// The test ends at e_end = max_k e_k. A curve still rising when the test
// stops has its largest value at the end, which says nothing about where it
// would peak, so the largest value is called a peak only before the last
// fraction f = 5 % of the test's progress:
//     peak  <=>  e_m < (1 - f) e_end.
// A largest value at e_m >= 0.95 e_end is "no peak reached: shear further".
#pragma once

#include <cstddef>
#include <optional>
#include <span>

namespace grainlab::analysis {

// The fraction f of the test's progress, at its end, where a largest value is
// not called a peak.
inline constexpr double kPeakEndFraction = 0.05;

// Whether a largest value at progress `at` is a peak in a test that ended at
// progress `end` (the rule above).
bool is_peak_at(double at, double end);

// Largest finite value of a series; nullopt when there is none.
std::optional<double> series_peak(std::span<const double> values);

struct CurvePeak {
  double value = 0;       // y_m, the largest finite value
  double at = 0;          // e_m, the progress at it
  std::size_t index = 0;  // m
  bool is_peak = false;   // is_peak_at(e_m, e_end)
};

// The largest finite value of `values` (the first where several are equal),
// where it is on `progress` (same length) and whether it is a peak; nullopt
// when no sample has both a finite value and a finite progress.
std::optional<CurvePeak> curve_peak(std::span<const double> values, std::span<const double> progress);

}  // namespace grainlab::analysis
