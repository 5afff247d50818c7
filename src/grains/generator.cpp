// Rounded random polytopes (see generator.h).
//
// Construction of one grain with target roundness R, elongation E, flatness F:
//  1. Core: M points lambda_k (u_x, b u_y, c u_z) with u_k uniform on the unit
//     sphere and lambda_k uniform in [0.8, 1] (so some points fall inside the
//     hull and the facets vary in size); its hull is a random convex polytope.
//  2. Corner radius: the outline of (core + ball(r)) projected on a plane is
//     (projected core) + disc(r). Its corners are arcs of radius r and its
//     largest inscribed circle has radius rin_p + r, where rin_p is that of the
//     projected core. The measured roundness (shape_metrics) averages
//     r / (rin_p + r) over the three principal planes, so r solves
//       (1/3) sum_p r / (rin_p + r) = R
//     (left side increasing in r from 0 to 1: bisection).
//  3. Aspect ratios: rounding adds 2 r to every extent, which makes the grain
//     stubbier than its core. b and c are corrected by fixed-point iteration
//     until (ext_y + 2 r) / (ext_x + 2 r) = E and (ext_z + 2 r)/(ext_y + 2 r) = F.
//     Measured roundness (after tessellation) runs above this model for small
//     r; the model target is shifted by the measured miss and the grain rebuilt
//     (at most kRoundnessAttempts times), keeping the closest. The roundness
//     is measured on at least 1000 faces (kRoundnessMeasureFaces): on fewer
//     the measure cannot see the rounding, and chasing the target turned
//     200-face rounded grains into balls (sphericity 0.99, elongation 0.96
//     against 0.82). A grain of fewer faces is the same body (core, r),
//     tessellated coarser; its measured roundness is then below the target.
//  4. Surface: rounded_hull_mesh samples core + ball(r) along faces/2 + 2
//     Fibonacci directions, whose hull has exactly `faces` triangles.
//  5. The mesh is moved to its centroid and rotated into its principal frame.
// R = 1 skips the core: the grain is a sphere (or an ellipsoid when E, F < 1).
//  6. Dents (convexity C < 1 only; no random draw otherwise, so convex grains
//     are the same bits as before). Two directions u1, u2 on different sides
//     are drawn (u2 flipped if u1.u2 > 0). A ball of radius rho = 0.5 (the
//     intermediate dimension is 1 here) comes in along each, its centre at
//     (h_k + rho - depth h_k) u_k with h_k the grain's support along u_k, and
//     every vertex inside it moves towards the centroid onto the ball's
//     surface: along the ray s d (d = v / |v|) the ball begins at
//       s1 = d.c - sqrt((d.c)^2 - |c|^2 + rho^2),
//     and v <- s1 d when 0 < s1 < |v|. The convex grain is star-shaped about
//     its centroid and no vertex changes direction, so the bitten surface
//     stays closed and free of self-intersection (the centroid stays outside
//     the balls: depth <= 0.8). Convexity V / V_hull falls as the depth grows:
//     it is bisected until it is C within 1e-4, on the mesh subdivided to
//     edges of at most 0.03 (a rounded hull's flat faces are single large
//     triangles, which a dent would cut into fans); the result is simplified
//     back to the face budget and the target corrected once for the convexity
//     the simplification moved. One such dent bottoms out near C = 0.865, two
//     near 0.755: C below kMinConvexity = 0.8 is refused.
#include "grains/generator.h"

#include "core/error.h"
#include "geometry/convex_hull.h"
#include "geometry/mass_properties.h"
#include "geometry/rounded_hull.h"
#include "geometry/shape_metrics.h"
#include "geometry/simplify.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <utility>

namespace grainlab {
namespace {

constexpr int kRoundnessAttempts = 4;        // generate-and-measure rounds per grain
constexpr double kRoundnessTolerance = 0.01;  // accepted |measured - target| roundness
// Faces of the tessellation the roundness is measured on while the corner
// radius is chosen (a grain of fewer faces is then tessellated from the same
// core and radius): measured on their own 200 faces, rounded grains (R 0.70)
// had reached at most 0.55, with a radius that made them balls.
constexpr int kRoundnessMeasureFaces = 1000;
// Floor on the corner radius (as model roundness r / (rin + r)): below it the
// samples of one corner crowd within single-precision STL resolution and merge
// when the file is read back.
constexpr double kMinModelRoundness = 0.03;

constexpr std::array<GrainPreset, 4> kPresets = {GrainPreset::GlassBeads, GrainPreset::Rounded,
                                                 GrainPreset::SubAngular, GrainPreset::Angular};

// Mean over the coordinate planes xy, xz, yz of r / (rin_p + r) for a corner radius r.
struct RoundnessOfRadius {
  std::array<double, 3> rin{};
  double operator()(double r) const {
    double s = 0;
    for (double v : rin) s += r / (v + r);
    return s / 3;
  }
};

RoundnessOfRadius core_inscribed_radii(const std::vector<Vec3>& core) {
  RoundnessOfRadius f;
  constexpr int kPlanes[3][2] = {{0, 1}, {0, 2}, {1, 2}};
  std::vector<Vec2> proj(core.size());
  for (int p = 0; p < 3; ++p) {
    for (std::size_t i = 0; i < core.size(); ++i) proj[i] = Vec2(core[i][kPlanes[p][0]], core[i][kPlanes[p][1]]);
    f.rin[p] = largest_inscribed_circle(convex_outline(proj));
  }
  return f;
}

// Corner radius giving roundness R for this core (bisection; f increases in r).
double corner_radius(const RoundnessOfRadius& f, double roundness) {
  double lo = 0, hi = 1;
  while (f(hi) < roundness) hi *= 2;
  for (int i = 0; i < 80; ++i) {
    const double mid = 0.5 * (lo + hi);
    (f(mid) < roundness ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// Centroid to the origin, principal axes (long, intermediate, short) to x, y, z.
TriMesh to_principal_frame(const TriMesh& mesh) {
  const PrincipalFrame f = principal_frame(mesh);
  TriMesh out = mesh;
  for (Vec3& v : out.vertices) v = f.axes.transpose() * (v - f.centroid);
  return out;
}

// Radius of the balls that bite the dents (step 6), grain intermediate dimension 1.
constexpr double kBiteRadius = 0.5;
// The mesh they bite: edges at most this long, or at most this many times the face budget.
constexpr double kDentMeshEdge = 0.03;
constexpr std::size_t kDentMeshFaceFactor = 16;

// Each triangle split into four at its edges' midpoints (shared midpoints
// shared), until no edge is longer than max_edge or the faces would pass
// max_faces.
TriMesh subdivided(TriMesh m, double max_edge, std::size_t max_faces) {
  const auto longest = [](const TriMesh& t) {
    double l = 0;
    for (const Face& f : t.faces)
      for (int k = 0; k < 3; ++k) l = std::max(l, (t.vertices[f[k]] - t.vertices[f[(k + 1) % 3]]).norm());
    return l;
  };
  while (longest(m) > max_edge && 4 * m.faces.size() <= max_faces) {
    std::map<std::pair<Index, Index>, Index> midpoint;
    const auto mid = [&](Index a, Index b) {
      const auto key = std::minmax(a, b);
      auto [it, fresh] = midpoint.try_emplace({key.first, key.second}, static_cast<Index>(m.vertices.size()));
      if (fresh) m.vertices.push_back(0.5 * (m.vertices[a] + m.vertices[b]));
      return it->second;
    };
    std::vector<Face> faces;
    faces.reserve(4 * m.faces.size());
    for (const Face& f : m.faces) {
      const Index ab = mid(f[0], f[1]), bc = mid(f[1], f[2]), ca = mid(f[2], f[0]);
      faces.push_back({f[0], ab, ca});
      faces.push_back({ab, f[1], bc});
      faces.push_back({ca, bc, f[2]});
      faces.push_back({ab, bc, ca});
    }
    m.faces = std::move(faces);
  }
  return m;
}

// Step 6 above: the grain (centroid at the origin, intermediate dimension
// about 1) bitten by two balls of radius kBiteRadius, about `u1` and `u2`,
// to the same depth, for convexity `target`.
TriMesh dented(const TriMesh& convex, const Vec3& u1, const Vec3& u2, double target) {
  const std::array<Vec3, 2> dirs = {u1, u2};
  std::array<double, 2> reach{};  // the grain's support along each direction
  for (int k = 0; k < 2; ++k)
    for (const Vec3& v : convex.vertices) reach[k] = std::max(reach[k], v.dot(dirs[k]));
  const auto bitten = [&](double depth) {
    TriMesh m = convex;
    for (int k = 0; k < 2; ++k) {
      const Vec3 c = (reach[k] + kBiteRadius - depth * reach[k]) * dirs[k];
      for (Vec3& v : m.vertices) {
        // The ray s d (d = v / |v|) enters the ball at s1 = d.c - sqrt((d.c)^2 - |c|^2 + rho^2).
        const double r = v.norm(), dc = v.dot(c) / r;
        const double disc = dc * dc - c.squaredNorm() + kBiteRadius * kBiteRadius;
        if (disc <= 0) continue;
        const double s1 = dc - std::sqrt(disc);
        if (s1 > 0 && s1 < r) v *= s1 / r;  // the centroid stays outside the ball: s1 > 0 on rays towards it
      }
    }
    return m;
  };
  // depth is a fraction of the reach: from balls clear of the grain (-rho /
  // reach and less) to balls whose surface stops short of the centroid by a
  // fifth of the reach (0.8).
  const double deepest = 0.8;
  if (convexity(bitten(deepest)) > target)
    input_error("grain convexity {} is out of reach of two dents (the deepest give {:.3f}): ask for at least {}",
                target, convexity(bitten(deepest)), kMinConvexity);
  double lo = -kBiteRadius / std::min(reach[0], reach[1]), hi = deepest;
  while (hi - lo > 1e-7) {
    const double mid = 0.5 * (lo + hi);
    const double c = convexity(bitten(mid));
    if (std::abs(c - target) < 1e-4) return bitten(mid);
    (c > target ? lo : hi) = mid;
  }
  return bitten(0.5 * (lo + hi));
}

}  // namespace

GrainPreset parse_grain_preset(const std::string& name) {
  for (GrainPreset p : kPresets) {
    if (name == grain_preset_name(p)) return p;
  }
  input_error("unknown grain preset '{}': use one of glass-beads, rounded, sub-angular, angular", name);
}

const char* grain_preset_name(GrainPreset preset) {
  switch (preset) {
    case GrainPreset::GlassBeads: return "glass-beads";
    case GrainPreset::Rounded: return "rounded";
    case GrainPreset::SubAngular: return "sub-angular";
    case GrainPreset::Angular: return "angular";
  }
  return "?";
}

std::string grain_preset_description(GrainPreset preset) {
  const GeneratorSpec s = preset_spec(preset);
  const char* sand = "";
  switch (preset) {
    case GrainPreset::GlassBeads: sand = "glass beads (spheres)"; break;
    case GrainPreset::Rounded: sand = "Ottawa sand (rounded)"; break;
    case GrainPreset::SubAngular: sand = "Griffin sand (sub-angular to sub-rounded)"; break;
    case GrainPreset::Angular: sand = "crushed limestone (very angular to sub-angular)"; break;
  }
  return fmt::format("{}: {}; roundness {:.2f}, elongation {:.2f}, flatness {:.2f}", grain_preset_name(preset),
                     sand, s.roundness, s.elongation, s.flatness);
}

GeneratorSpec preset_spec(GrainPreset preset) {
  GeneratorSpec s;
  s.preset = preset;
  switch (preset) {
    case GrainPreset::GlassBeads:
      s.roundness = 1.0;
      s.elongation = 1.0;
      s.flatness = 1.0;
      s.roundness_spread = 0;
      s.aspect_spread = 0;
      break;
    case GrainPreset::Rounded:
      s.roundness = 0.70;
      s.elongation = 0.82;
      s.flatness = 0.82;
      s.corners = 20;
      break;
    case GrainPreset::SubAngular:
      s.roundness = 0.45;
      s.elongation = 0.75;
      s.flatness = 0.75;
      s.corners = 16;
      break;
    case GrainPreset::Angular:
      s.roundness = 0.22;
      s.elongation = 0.70;
      s.flatness = 0.68;
      s.corners = 12;
      s.roundness_spread = 0.04;
      break;
  }
  return s;
}

void validate(const GeneratorSpec& s) {
  if (!(s.roundness > 0 && s.roundness <= 1)) {
    input_error("grain roundness must be in (0, 1] (1 = sphere), got {}", s.roundness);
  }
  if (!(s.elongation > 0 && s.elongation <= 1)) {
    input_error("grain elongation (intermediate / long axis) must be in (0, 1], got {}", s.elongation);
  }
  if (!(s.flatness > 0 && s.flatness <= 1)) {
    input_error("grain flatness (short / intermediate axis) must be in (0, 1], got {}", s.flatness);
  }
  if (s.faces < 20) input_error("grain face budget must be at least 20, got {}", s.faces);
  if (s.corners < 6) input_error("grain core needs at least 6 corner points, got {}", s.corners);
  if (!(s.convexity >= kMinConvexity && s.convexity <= 1)) {
    input_error("grain convexity (volume / convex hull volume) must be in [{}, 1] (1 = convex, no dent), got {}",
                kMinConvexity, s.convexity);
  }
  if (!(s.roundness_spread >= 0) || !(s.aspect_spread >= 0)) {
    input_error("grain shape spreads must be >= 0, got roundness {} and aspect {}", s.roundness_spread,
                s.aspect_spread);
  }
}

namespace {

// Steps 1-5 above: the convex grain.
TriMesh generate_convex_grain(const GeneratorSpec& spec, Rng& rng) {
  // Per-grain targets; the draws happen in a fixed order whatever the preset.
  const double du = rng.uniform(-1.0, 1.0), de = rng.uniform(-1.0, 1.0), df = rng.uniform(-1.0, 1.0);
  const double e = std::clamp(spec.elongation + spec.aspect_spread * de, 0.2, 1.0);
  const double fl = std::clamp(spec.flatness + spec.aspect_spread * df, 0.2, 1.0);
  if (spec.roundness >= 1.0) {
    // Sphere, stretched to an ellipsoid when the aspect ratios ask for it.
    const std::vector<Vec3> centre = {Vec3::Zero()};
    TriMesh m = rounded_hull_mesh(centre, 0.5, spec.faces);
    for (Vec3& v : m.vertices) v = Vec3(v.x() / e, v.y(), v.z() * fl);
    return to_principal_frame(m);
  }
  const double roundness = std::clamp(spec.roundness + spec.roundness_spread * du, 0.02, 0.98);

  std::vector<Vec3> dirs(static_cast<std::size_t>(spec.corners));
  std::vector<double> lambda(dirs.size());
  for (std::size_t k = 0; k < dirs.size(); ++k) {
    dirs[k] = rng.unit_vector();
    lambda[k] = rng.uniform(0.8, 1.0);
  }
  double b = e, c = e * fl, r = 0;
  std::vector<Vec3> core(dirs.size());
  for (int iter = 0; iter < 6; ++iter) {
    for (std::size_t k = 0; k < dirs.size(); ++k) {
      core[k] = lambda[k] * Vec3(dirs[k].x(), b * dirs[k].y(), c * dirs[k].z());
    }
    r = corner_radius(core_inscribed_radii(core), roundness);
    Vec3 lo = core[0], hi = core[0];
    for (const Vec3& p : core) {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
    const Vec3 ext = (hi - lo).array() + 2 * r;
    const double got_e = ext.y() / ext.x(), got_ef = ext.z() / ext.x();
    b = std::max(0.02, b * e / got_e);
    c = std::max(0.02, c * e * fl / got_ef);
  }
  // Measured roundness sits above the model's at small r (the tessellation and
  // the metric's smoothing floor blunt the sharpest corners): correct the model
  // target by the measured miss, keeping the closest of a few attempts.
  // Measured on at least kRoundnessMeasureFaces (see there), then the grain
  // is tessellated at its own budget from the same core and radius.
  const RoundnessOfRadius model = core_inscribed_radii(core);
  const int measure_faces = std::max(spec.faces, kRoundnessMeasureFaces);
  double model_target = roundness, best_miss = std::numeric_limits<double>::infinity(), best_r = 0;
  TriMesh best;
  for (int attempt = 0; attempt < kRoundnessAttempts; ++attempt) {
    r = corner_radius(model, model_target);
    TriMesh trial = rounded_hull_mesh(core, r, measure_faces);
    const double measured = shape_metrics(trial).roundness;
    const double miss = measured - roundness;
    if (std::abs(miss) < best_miss) {
      best_miss = std::abs(miss);
      best = std::move(trial);
      best_r = r;
    }
    if (std::abs(miss) < kRoundnessTolerance) break;
    model_target = std::clamp(model_target - miss, kMinModelRoundness, 0.998);
  }
  if (measure_faces != spec.faces) best = rounded_hull_mesh(core, best_r, spec.faces);
  TriMesh m = to_principal_frame(best);
  // Unit intermediate dimension keeps numbers readable before the grain is sized.
  const double s = 1.0 / principal_frame(m).extents[1];
  for (Vec3& v : m.vertices) v *= s;
  return m;
}

}  // namespace

TriMesh generate_grain(const GeneratorSpec& spec, Rng& rng) {
  validate(spec);
  TriMesh m = generate_convex_grain(spec, rng);
  if (spec.convexity >= 1) return m;
  const Vec3 u1 = rng.unit_vector();
  Vec3 u2 = rng.unit_vector();
  if (u2.dot(u1) > 0) u2 = -u2;  // the two dents on different sides
  // Bitten on a fine mesh (a rounded hull's flat faces are single large
  // triangles, which a dent would cut into fans), then simplified back to the
  // face budget; the target is corrected once by the convexity the
  // simplification moved.
  const TriMesh fine = subdivided(m, kDentMeshEdge, kDentMeshFaceFactor * static_cast<std::size_t>(spec.faces));
  double target = spec.convexity;
  for (int attempt = 0; attempt < 2; ++attempt) {
    m = simplify_mesh(dented(fine, u1, u2, target), spec.faces).mesh;
    target = std::clamp(target + spec.convexity - convexity(m), 0.5, 1.0);
  }
  m = to_principal_frame(m);
  const double s = 1.0 / principal_frame(m).extents[1];
  for (Vec3& v : m.vertices) v *= s;
  return m;
}

}  // namespace grainlab
