// The solid fraction of a packing inside an axis-aligned region, away from
// the walls that loosen it.
//
// Each grain counts with the part of its volume inside the region, taken as
// the part of its equal-volume sphere (radius r, centre c) inside: along one
// axis, the fraction of a sphere below the plane c + h is the cap formula
//   F(h) = (r + h)^2 (2 r - h) / (4 r^3)  for |h| <= r (0 below, 1 above),
// so the fraction between planes a and b is F(b - c) - F(a - c), and the
// fraction inside the box is the product over the three axes. For spheres
// cut by one face this is exact; at the region's edges and corners (a small
// share of the grains) the product slightly differs from the true
// intersection, and for faceted grains the equal-volume sphere stands for the
// grain. Counting whole grains by their centre would also be unbiased, but
// noisier (grains on the faces count all or nothing).
// Solid fraction phi = sum(V_i f_i) / V_region, void ratio e = 1/phi - 1.
#pragma once

#include "dynamics/model.h"
#include "dynamics/state.h"

namespace grainlab {

// Solid fraction of the grains of (m, s) inside the box [lo, hi] (m).
double solid_fraction_in_region(const Model& m, const State& s, const Vec3& lo, const Vec3& hi);

// Wall margin of a bulk region: 1.5 mean grain diameters (the layer touching
// a wall, centres within half a diameter, is the loosest; the oscillation of
// the density beyond it averages out), at most a quarter of the box.
inline constexpr double kBulkMarginDiameters = 1.5;

// A box region: lower and upper corners (m).
struct Region {
  Vec3 lo = Vec3::Zero(), hi = Vec3::Zero();
};

// The bulk of a specimen in the box |x| <= L/2, |y| <= W/2, 0 <= z <= top:
// kBulkMarginDiameters x d from every side (from the top too).
Region bulk_region(double length, double width, double top, double mean_diameter);

// Void ratio 1/phi - 1 inside [lo, hi]; +infinity if no grain is inside.
double void_ratio_in_region(const Model& m, const State& s, const Vec3& lo, const Vec3& hi);

}  // namespace grainlab
