// Otsu's threshold: the grey level that splits a histogram into two classes
// with the largest between-class variance.
//
// With a histogram of B equal bins over [lo, hi], class probabilities
// w0(t) = sum_{b<=t} p_b, w1 = 1 - w0 and means m0(t), m1(t), the
// between-class variance is s_B^2(t) = w0 w1 (m0 - m1)^2
// = (m_T w0 - m(t))^2 / (w0 (1 - w0)) with m(t) = sum_{b<=t} p_b x_b and m_T
// the overall mean (Otsu 1979). The threshold is the upper edge of the best
// bin t; voxels above it are solid. For a scan of grains in air or resin the
// two classes are pore and grain.
#pragma once

#include <span>

namespace grainlab::ct {

struct OtsuResult {
  float threshold = 0;        // solid: value > threshold
  double background_mean = 0; // mean of the values at or below it
  double foreground_mean = 0; // mean of the values above it
};

// Otsu on a 256-bin histogram of `values` between their minimum and maximum.
// Requires at least two distinct values (callers check).
OtsuResult otsu_threshold(std::span<const float> values, int bins = 256);

// Class means for a given threshold (user's --threshold).
OtsuResult class_means(std::span<const float> values, float threshold);

}  // namespace grainlab::ct
