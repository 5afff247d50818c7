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
//     are the same bits as before). Two directions u1, u2 are drawn on
//     opposite sides, at least 120 degrees apart (u2 flipped when u1.u2 > 0,
//     drawn again while u1.u2 > -1/2). Each presses a crater into the grain:
//     a point v of the surface, at angle theta = acos(d.u) from u (d = v/|v|),
//     moves towards the centroid to
//       v <- (1 - D w(x)) v,   x = clamp((theta0 - theta) / delta, 0, 1),
//       w(x) = x^3 (6 x^2 - 15 x + 10)   (smootherstep: w, w', w'' vanish at
//                                          x = 0 and w', w'' at x = 1),
//     the two factors multiplied where craters meet. The crater's rim is at
//     theta0 = 1.15 rad, its wall delta = 0.25 rad wide, and its floor at
//     (1 - D) of the grain's radius there. No vertex changes direction and
//     every scale factor is positive, so the surface stays closed and
//     star-shaped about the centroid, free of self-intersection; the radius
//     is C2 in the direction, so rim and foot of the wall are round, not a
//     crease. (The first build bit balls into the grain along rays: where a
//     grain reached past a ball's silhouette, the bite was a radial cliff,
//     cut along the mesh edges into sub-voxel teeth, which no scan resolves;
//     docs/ct.md.) Convexity V / V_hull falls as D grows: D is bisected until
//     it is C within 1e-4, on a fine mesh (refined_radially: the grain's
//     vertices plus points every 0.03 or so, triangulated by the hull of their
//     directions); the result is simplified back to the face budget and the
//     target corrected for the convexity the simplification moved, keeping
//     the closest of kDentAttempts. D = 0.95 (kDentDeepest) reaches C = 0.77-
//     0.79 (spheres the most convex); C below kMinConvexity = 0.8 is refused.
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
#include <numbers>
#include <optional>
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
TriMesh to_principal_frame(TriMesh mesh) {
  move_to_principal_frame(mesh);
  return mesh;
}

// A dent seen from the centroid (step 6): its rim's half-angle and the width of the wall, radians.
constexpr double kDentHalfAngle = 1.15;
constexpr double kDentWall = 0.25;
// The mesh the dents are pressed into: its edges at most this long.
constexpr double kDentMeshEdge = 0.03;
// Depth of the deepest dents: the floor at a twentieth of the grain's radius there.
constexpr double kDentDeepest = 0.95;
// Attempts at the convexity through the simplification, and the miss that ends them.
constexpr int kDentAttempts = 4;
constexpr double kDentTolerance = 5e-4;
// Volume change allowed when it is simplified back to the face budget (the grain is rescaled and its
// convexity corrected afterwards).
constexpr double kDentSimplifyVolume = 0.03;

// The convex grain (centroid at the origin) refined for the dents: its own
// vertices plus points along the Fibonacci directions of rounded_hull_mesh's
// sphere, each where its ray leaves the grain (the nearest of the face planes
// it crosses), less those closer in direction to one of the grain's vertices
// than half their spacing. The grain is star-shaped about its centroid, so
// the hull of the points' directions triangulates them: a fine, regular mesh
// of the same body, with edges of about max_edge where the grain reaches
// farthest (at least `min_faces` faces), which keeps the grain's vertices for
// the simplification to return to.
TriMesh refined_radially(const TriMesh& convex, double max_edge, int min_faces) {
  std::vector<std::pair<Vec3, double>> planes;  // n . x <= offset inside
  for (const Face& f : convex.faces) {
    const Vec3& a = convex.vertices[f[0]];
    const Vec3 n = (convex.vertices[f[1]] - a).cross(convex.vertices[f[2]] - a);
    if (n.squaredNorm() > 0) planes.emplace_back(n.normalized(), n.normalized().dot(a));
  }
  double reach = 0;
  for (const Vec3& v : convex.vertices) reach = std::max(reach, v.norm());
  // N points on a sphere of radius `reach` are about sqrt(8 pi / (sqrt 3 N)) reach apart.
  const double n_points = std::max(8 * std::numbers::pi / std::sqrt(3.0) * (reach / max_edge) * (reach / max_edge),
                                   0.5 * min_faces);
  const double spacing = std::sqrt(8 * std::numbers::pi / (std::sqrt(3.0) * n_points));  // radians
  const std::vector<Vec3> centre = {Vec3::Zero()};
  const TriMesh sphere = rounded_hull_mesh(centre, 1.0, static_cast<int>(2 * n_points));
  std::vector<Vec3> points = convex.vertices, directions;
  for (const Vec3& v : convex.vertices) directions.push_back(v.normalized());
  const double too_close = std::cos(0.5 * spacing);
  for (const Vec3& v : sphere.vertices) {
    const Vec3 d = v.normalized();
    if (std::any_of(directions.begin(), directions.begin() + static_cast<std::ptrdiff_t>(convex.vertices.size()),
                    [&](const Vec3& e) { return e.dot(d) > too_close; }))
      continue;
    double t = std::numeric_limits<double>::infinity();
    for (const auto& [n, offset] : planes)
      if (n.dot(d) > 0) t = std::min(t, offset / n.dot(d));
    points.push_back(t * d);
    directions.push_back(d);
  }
  const ConvexHull hull = convex_hull(directions);
  TriMesh m;
  for (const Index i : hull.input_index) m.vertices.push_back(points[i]);
  m.faces = hull.faces;
  return m;
}

// Step 6 above: two craters about u1 and u2 on a grain (centroid at the
// origin). Each vertex's crater weights w(x) do not depend on the depth, so
// they are computed once; the depth D is bisected for a convexity.
class Craters {
 public:
  Craters(const TriMesh& grain, const Vec3& u1, const Vec3& u2) : grain_(grain), weights_(grain.vertices.size()) {
    const std::array<Vec3, 2> dirs = {u1, u2};
    for (std::size_t i = 0; i < grain.vertices.size(); ++i) {
      const Vec3 d = grain.vertices[i].normalized();
      for (int k = 0; k < 2; ++k) {
        const double x =
            std::clamp((kDentHalfAngle - std::acos(std::clamp(d.dot(dirs[k]), -1.0, 1.0))) / kDentWall, 0.0, 1.0);
        weights_[i][k] = x * x * x * (x * (6 * x - 15) + 10);
      }
    }
    deepest_ = convexity(pressed(kDentDeepest));
  }

  // The convexity of the deepest craters (D = kDentDeepest).
  double deepest() const { return deepest_; }

  // The grain pressed in to depth D: v <- (1 - D w1)(1 - D w2) v.
  TriMesh pressed(double depth) const {
    TriMesh m = grain_;
    for (std::size_t i = 0; i < m.vertices.size(); ++i)
      m.vertices[i] *= (1 - depth * weights_[i][0]) * (1 - depth * weights_[i][1]);
    return m;
  }

  // The grain at convexity `target` (within 1e-4); nothing when the deepest craters leave it above.
  std::optional<TriMesh> at_convexity(double target) const {
    if (deepest_ > target) return std::nullopt;
    double lo = 0, hi = kDentDeepest;
    while (hi - lo > 1e-7) {
      const double mid = 0.5 * (lo + hi);
      const double c = convexity(pressed(mid));
      if (std::abs(c - target) < 1e-4) return pressed(mid);
      (c > target ? lo : hi) = mid;
    }
    return pressed(0.5 * (lo + hi));
  }

 private:
  const TriMesh& grain_;
  std::vector<std::array<double, 2>> weights_;
  double deepest_ = 1;
};

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
  Vec3 u2 = -u1;
  do {  // the two dents on opposite sides, at least 120 degrees apart
    u2 = rng.unit_vector();
    if (u2.dot(u1) > 0) u2 = -u2;
  } while (u2.dot(u1) > -0.5);
  // Pressed into a fine mesh, then simplified back to the face budget; the
  // target corrected by the convexity the simplification moved, keeping the
  // closest of a few attempts.
  const TriMesh fine = refined_radially(m, kDentMeshEdge, 4 * spec.faces);
  const Craters craters(fine, u1, u2);
  if (craters.deepest() > spec.convexity) {
    input_error("grain convexity {} is out of reach of two dents (the deepest give {:.3f}): ask for at least {}",
                spec.convexity, craters.deepest(), kMinConvexity);
  }
  double target = spec.convexity, best_miss = std::numeric_limits<double>::infinity();
  for (int attempt = 0; attempt < kDentAttempts && best_miss > kDentTolerance; ++attempt) {
    const std::optional<TriMesh> pressed = craters.at_convexity(target);
    if (!pressed) break;  // a corrected target beyond reach: keep the closest so far
    TriMesh trial = simplify_mesh(*pressed, spec.faces, kDentSimplifyVolume).mesh;
    const double miss = convexity(trial) - spec.convexity;
    if (std::abs(miss) < best_miss) {
      best_miss = std::abs(miss);
      m = std::move(trial);
    }
    target = std::clamp(target - miss, 0.5, 1.0);
  }
  m = to_principal_frame(m);
  const double s = 1.0 / principal_frame(m).extents[1];
  for (Vec3& v : m.vertices) v *= s;
  return m;
}

}  // namespace grainlab
