// Scene layout: grains are drawn in turn (the shape cycles through the kinds
// below), scaled to a random intermediate dimension, turned by a random
// rotation, and placed at random where their bounding spheres keep 2 voxels
// from every other grain and from the image faces. The second grain of a
// touching pair is placed along a random direction from the first at the
// distance where the two meshes just touch (bisection on "a vertex of one is
// inside the other"), then 0.3 voxel closer, so the scan shows a neck a
// watershed must cut.
#include "ct/synthetic_volume.h"

#include "core/error.h"
#include "core/rng.h"
#include "ct/voxelize.h"
#include "geometry/mass_properties.h"
#include "geometry/primitives.h"
#include "grains/generator.h"
#include "grains/grain_set.h"

#include <algorithm>
#include <cmath>

namespace grainlab::ct {

namespace {

constexpr double kGap = 2.0;        // voxels between bounding spheres, and to the image faces
constexpr double kOverlap = 0.3;    // voxels a touching pair is pressed together
constexpr int kPlacementTries = 2000;

// A grain in voxel-index coordinates, centred at its centroid, of intermediate dimension `size`.
TriMesh make_grain(int n, double size, Rng& rng, std::string* kind) {
  TriMesh m;
  switch (n % 4) {
    case 0: {
      *kind = "ellipsoid";
      const double b = rng.uniform(0.75, 0.9), c = rng.uniform(0.6, 0.75);
      m = ellipsoid_mesh(1.0, b, c, 4);
      break;
    }
    case 1:
    case 2: {
      *kind = n % 4 == 1 ? "rounded" : "sub-angular";
      GeneratorSpec spec = preset_spec(n % 4 == 1 ? GrainPreset::Rounded : GrainPreset::SubAngular);
      m = generate_grain(spec, rng);
      break;
    }
    default: {
      *kind = "concave";
      GeneratorSpec spec = preset_spec(GrainPreset::Rounded);
      spec.convexity = 0.88;
      m = generate_grain(spec, rng);
      break;
    }
  }
  const double scale = size / size_of(m);
  const Vec3 c = mass_properties(m).centroid;
  for (Vec3& v : m.vertices) v = (v - c) * scale;
  return m;
}

double bounding_radius(const TriMesh& m) {
  double r = 0;
  for (const Vec3& v : m.vertices) r = std::max(r, v.norm());
  return r;
}

TriMesh moved(const TriMesh& m, const Quat& q, const Vec3& t) {
  TriMesh out = m;
  for (Vec3& v : out.vertices) v = q * v + t;
  return out;
}

// True when a vertex of one mesh is inside the other (bounding boxes first).
bool overlapping(const TriMesh& a, const TriMesh& b) {
  auto box = [](const TriMesh& m, Vec3& lo, Vec3& hi) {
    lo = hi = m.vertices.front();
    for (const Vec3& v : m.vertices) {
      lo = lo.cwiseMin(v);
      hi = hi.cwiseMax(v);
    }
  };
  Vec3 alo, ahi, blo, bhi;
  box(a, alo, ahi);
  box(b, blo, bhi);
  auto any_inside = [](const TriMesh& verts, const TriMesh& solid, const Vec3& lo, const Vec3& hi) {
    for (const Vec3& v : verts.vertices) {
      if ((v.array() >= lo.array()).all() && (v.array() <= hi.array()).all() && inside_mesh(solid, v)) return true;
    }
    return false;
  };
  return any_inside(a, b, blo, bhi) || any_inside(b, a, alo, ahi);
}

}  // namespace

void validate(const SyntheticSpec& s) {
  if (s.size < 16 || s.size > 2048) input_error("synthetic volume size {} must be 16-2048 voxels", s.size);
  if (!(s.voxel_size > 0)) input_error("synthetic voxel size {} must be positive (m)", s.voxel_size);
  if (s.grains < 1) input_error("synthetic grain count {} must be at least 1", s.grains);
  if (s.touching_pairs < 0 || 2 * s.touching_pairs > s.grains) {
    input_error("{} touching pairs need at least {} grains", s.touching_pairs, 2 * s.touching_pairs);
  }
  if (!(s.grain_size >= 6 && s.grain_size < s.size / 1.5)) {
    input_error("synthetic grain size {} voxels must be at least 6 and well below the volume size {}", s.grain_size,
                s.size);
  }
  if (s.blur < 0 || s.noise < 0 || s.samples < 1) input_error("blur, noise and samples must not be negative");
}

SyntheticScene make_synthetic_scene(const SyntheticSpec& spec) {
  validate(spec);
  Rng rng(spec.seed);
  SyntheticScene scene;
  struct Placed {
    TriMesh mesh;  // voxel-index coordinates
    Vec3 centre;
    double radius;
  };
  std::vector<Placed> placed;
  const double n = static_cast<double>(spec.size);
  auto fits = [&](const Vec3& c, double r, int skip) {
    for (int a = 0; a < 3; ++a) {
      if (c[a] - r < kGap || c[a] + r > n - 1 - kGap) return false;
    }
    for (int q = 0; q < static_cast<int>(placed.size()); ++q) {
      if (q != skip && (placed[q].centre - c).norm() < placed[q].radius + r + kGap) return false;
    }
    return true;
  };
  for (int g = 0; g < spec.grains; ++g) {
    std::string kind;
    const TriMesh shape = make_grain(g, spec.grain_size * rng.uniform(0.85, 1.15), rng, &kind);
    const double r = bounding_radius(shape);
    const bool second_of_pair = g % 2 == 1 && g < 2 * spec.touching_pairs;
    bool done = false;
    for (int attempt = 0; attempt < kPlacementTries && !done; ++attempt) {
      const Quat q = rng.rotation();
      if (!second_of_pair) {
        // One draw a statement (a call's argument order is the compiler's).
        const double lo = r + kGap, hi = n - 1 - kGap - r;
        const double cz = rng.uniform(lo, hi), cy = rng.uniform(lo, hi), cx = rng.uniform(lo, hi);
        const Vec3 c(cx, cy, cz);
        if (!fits(c, r, -1)) continue;
        placed.push_back({moved(shape, q, c), c, r});
        done = true;
      } else {
        // Slide along u from the partner until the meshes touch, then press them kOverlap together.
        const Placed& a = placed.back();
        const Vec3 u = rng.unit_vector();
        double lo = 0, hi = a.radius + r;  // overlapping at lo (same centre), apart at hi
        for (int it = 0; it < 30; ++it) {
          const double mid = 0.5 * (lo + hi);
          (overlapping(a.mesh, moved(shape, q, a.centre + mid * u)) ? lo : hi) = mid;
        }
        const Vec3 c = a.centre + (hi - kOverlap) * u;
        // Only grains other than the partner must keep their distance.
        if (!fits(c, r, static_cast<int>(placed.size()) - 1)) continue;
        placed.push_back({moved(shape, q, c), c, r});
        scene.touching.emplace_back(g - 1, g);
        done = true;
      }
    }
    if (!done) {
      throw RunError(fmt::format("cannot place synthetic grain {} of {} in a {}^3 volume: use fewer or smaller "
                                 "grains or a larger volume",
                                 g + 1, spec.grains, spec.size));
    }
    scene.grains.push_back({kind, {}});
  }

  // Voxelize, blur, add noise.
  GreyVolume occ;
  occ.size = {spec.size, spec.size, spec.size};
  occ.spacing = Vec3::Constant(spec.voxel_size);
  occ.allocate(0.0f);
  for (const Placed& p : placed) add_occupancy(p.mesh, spec.samples, occ);
  for (float& v : occ.values) v = std::min(v, 1.0f);
  gaussian_blur(occ, spec.blur);
  const float contrast = spec.solid_level - spec.pore_level;
  for (float& v : occ.values) {
    v = spec.pore_level + contrast * v + static_cast<float>(spec.noise * contrast * rng.normal());
  }
  scene.volume = std::move(occ);
  for (std::size_t g = 0; g < placed.size(); ++g) {
    TriMesh m = placed[g].mesh;
    for (Vec3& v : m.vertices) v = scene.volume.world(v);
    scene.grains[g].mesh = std::move(m);
  }
  return scene;
}

}  // namespace grainlab::ct
