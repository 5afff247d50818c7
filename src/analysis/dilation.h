// Dilation angle series of a shear test (paper Eq. 19).
//
// psi = atan(d d_v / d d_h), with d_v the vertical displacement of the cap
// (up = dilation = positive) and d_h the horizontal box displacement. Single
// sample intervals are noisy, so the derivative at sample k is the central
// difference over +-h samples (h = 2 by default), clipped at the ends of the
// series:
//     psi_k = atan((d_v[hi] - d_v[lo]) / (d_h[hi] - d_h[lo])),
//     lo = max(0, k - h), hi = min(n - 1, k + h).
// Undefined (NaN) where d_h does not advance over the window (d_h[hi] <= d_h[lo]).
// For d_v = a d_h + b it is atan(a) at every sample.
#pragma once

#include <span>
#include <vector>

namespace grainlab::analysis {

// psi_k in degrees for every sample (rules above); d_h and d_v in the same unit.
std::vector<double> dilation_angle_series(std::span<const double> d_h, std::span<const double> d_v,
                                          int half_width = 2);

}  // namespace grainlab::analysis
