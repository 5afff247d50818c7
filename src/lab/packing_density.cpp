// Solid fraction in a region (derivation in packing_density.h).
#include "lab/packing_density.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace grainlab {

namespace {

// Fraction of a sphere of radius r below the plane at signed distance h from its centre.
double below(double h, double r) {
  if (h <= -r) return 0;
  if (h >= r) return 1;
  return (r + h) * (r + h) * (2 * r - h) / (4 * r * r * r);
}

}  // namespace

double solid_fraction_in_region(const Model& m, const State& s, const Vec3& lo, const Vec3& hi) {
  double solid = 0;
  for (std::size_t i = 0; i < m.bodies.size(); ++i) {
    const BodyModel& b = m.bodies[i];
    const double volume = m.shapes[b.shape].volume * b.scale * b.scale * b.scale;
    const double r = std::cbrt(3 * volume / (4 * std::numbers::pi));
    double f = 1;
    for (int k = 0; k < 3 && f > 0; ++k) {
      const double c = s.bodies[i].x[k];
      f *= below(hi[k] - c, r) - below(lo[k] - c, r);
    }
    solid += f * volume;
  }
  const Vec3 size = hi - lo;
  return solid / (size.x() * size.y() * size.z());
}

Region bulk_region(double length, double width, double top, double mean_diameter) {
  const double m = std::min({kBulkMarginDiameters * mean_diameter, 0.25 * length, 0.25 * width, 0.25 * top});
  return {Vec3(-0.5 * length + m, -0.5 * width + m, m), Vec3(0.5 * length - m, 0.5 * width - m, top - m)};
}

double void_ratio_in_region(const Model& m, const State& s, const Vec3& lo, const Vec3& hi) {
  const double phi = solid_fraction_in_region(m, s, lo, hi);
  return phi > 0 ? 1 / phi - 1 : std::numeric_limits<double>::infinity();
}

}  // namespace grainlab
