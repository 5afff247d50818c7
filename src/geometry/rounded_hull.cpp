// Sphere-swept convex polytopes (see rounded_hull.h).
//
// The support function of a Minkowski sum is the sum of the support functions:
// h_{P+B(r)}(u) = h_P(u) + r, attained at x(u) = argmax_{p in P} p . u + r u.
// Each x(u) lies on the boundary of P + B(r), and because the ball is strictly
// convex it is an exposed point (the only surface point with outward normal u),
// hence a vertex of the hull of all samples. n samples in convex position give
// a triangulated hull of 2 n - 4 faces. The polytope between samples is the
// inscribed approximation of the rounded solid: its largest gap to the true
// surface is about r (1 - cos(theta / 2)) for angular sample spacing theta.
#include "geometry/rounded_hull.h"

#include "core/error.h"
#include "geometry/convex_hull.h"

#include <cmath>
#include <numbers>

namespace grainlab {

std::vector<Vec3> fibonacci_directions(int n) {
  if (n < 4) input_error("fibonacci_directions: need at least 4 directions, got {}", n);
  std::vector<Vec3> out;
  out.reserve(static_cast<std::size_t>(n));
  const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < n; ++i) {
    const double z = 1.0 - 2.0 * (i + 0.5) / n;
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    out.emplace_back(r * std::cos(golden * i), r * std::sin(golden * i), z);
  }
  return out;
}

TriMesh rounded_hull_mesh(std::span<const Vec3> core, double radius, int faces) {
  if (core.empty()) input_error("rounded_hull_mesh: the core point set is empty");
  if (!(radius >= 0) || !std::isfinite(radius)) {
    input_error("rounded_hull_mesh: radius must be >= 0 and finite, got {}", radius);
  }
  if (faces < 8) input_error("rounded_hull_mesh: need at least 8 faces, got {}", faces);
  if (radius == 0) return convex_hull(core).mesh();
  const std::vector<Vec3> dirs = fibonacci_directions(faces / 2 + 2);
  std::vector<Vec3> samples;
  samples.reserve(dirs.size());
  for (const Vec3& u : dirs) {
    // Support point of the core; ties go to the first point, so output is deterministic.
    std::size_t best = 0;
    double best_h = core[0].dot(u);
    for (std::size_t i = 1; i < core.size(); ++i) {
      const double h = core[i].dot(u);
      if (h > best_h) {
        best_h = h;
        best = i;
      }
    }
    samples.push_back(core[best] + radius * u);
  }
  return convex_hull(samples).mesh();
}

}  // namespace grainlab
