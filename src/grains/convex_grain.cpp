// Ellipsoidal convex grains (see convex_grain.h).
#include "grains/convex_grain.h"

#include "geometry/convex_hull.h"
#include "geometry/mass_properties.h"

#include <cmath>
#include <numbers>

namespace grainlab {

TriMesh convex_grain(const ConvexGrainSpec& spec, Rng& rng) {
  const double b = spec.elongation + rng.uniform(-0.05, 0.05);
  const double c = b * (spec.flatness + rng.uniform(-0.05, 0.05));
  // Random smooth bumps: a few random cosine lobes on the sphere.
  Vec3 lobe_dir[4];
  double lobe_amp[4];
  for (int k = 0; k < 4; ++k) {
    lobe_dir[k] = rng.unit_vector();
    lobe_amp[k] = spec.bumpiness * rng.uniform(-1.0, 1.0);
  }
  const Quat spin = rng.rotation();
  std::vector<Vec3> pts;
  pts.reserve(spec.points);
  const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < spec.points; ++i) {
    const double z = 1.0 - 2.0 * (i + 0.5) / spec.points;
    const double r = std::sqrt(1.0 - z * z);
    const Vec3 u = spin * Vec3(r * std::cos(golden * i), r * std::sin(golden * i), z);
    double radial = 1.0;
    for (int k = 0; k < 4; ++k) radial += lobe_amp[k] * u.dot(lobe_dir[k]) * u.dot(lobe_dir[k]);
    pts.emplace_back(radial * u.x(), radial * b * u.y(), radial * c * u.z());
  }
  const ConvexHull hull = convex_hull(pts);
  TriMesh mesh = hull.mesh();
  const MassProperties mp = mass_properties(mesh);
  const double target = 4.0 / 3.0 * std::numbers::pi * std::pow(spec.equivalent_radius, 3);
  const double s = std::cbrt(target / mp.volume);
  for (Vec3& v : mesh.vertices) v = s * (v - mp.centroid);
  return mesh;
}

}  // namespace grainlab
