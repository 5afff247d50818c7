// Least-squares straight line y = a + b x through points added one at a time:
//   b = (n Sxy - Sx Sy) / (n Sxx - Sx^2),
// with Sx, Sy, Sxx, Sxy the sums over the n points. Undefined (NaN) with
// fewer than two points or with all x equal. For the short, O(1) series of
// the lab summaries the plain sums lose nothing that matters.
#pragma once

#include <limits>

namespace grainlab {

struct LineFit {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  int n = 0;

  void add(double x, double y) { sx += x, sy += y, sxx += x * x, sxy += x * y, ++n; }

  double slope() const {
    const double d = n * sxx - sx * sx;
    return n >= 2 && d > 0 ? (n * sxy - sx * sy) / d : std::numeric_limits<double>::quiet_NaN();
  }
};

}  // namespace grainlab
