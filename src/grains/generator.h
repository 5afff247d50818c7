// Synthetic sand grains with controlled angularity: a random convex polytope
// (the hull of random points near an ellipsoid) whose corners and edges are
// rounded by a sphere of radius r, i.e. the Minkowski sum core + ball(r);
// optionally with one smooth dent, for a chosen convexity.
// Every corner of such a grain's projection outline is a circular arc of radius
// r, so Wadell roundness is set directly by r (see docs/grains.md).
#pragma once

#include "core/rng.h"
#include "geometry/trimesh.h"

#include <string>

namespace grainlab {

// The paper's four sands, as angularity classes.
enum class GrainPreset {
  GlassBeads,  // spheres, roundness 1
  Rounded,     // Ottawa sand
  SubAngular,  // Griffin sand
  Angular,     // crushed limestone
};

// "glass-beads" | "rounded" | "sub-angular" | "angular"; InputError listing them otherwise.
GrainPreset parse_grain_preset(const std::string& name);
// The command-line name of a preset.
const char* grain_preset_name(GrainPreset preset);
// One line saying which sand the preset stands for and its default shape.
std::string grain_preset_description(GrainPreset preset);

// What to generate. Shape targets are means; each grain draws its own value
// uniformly within +- the spread (then clamped to a valid range).
struct GeneratorSpec {
  GrainPreset preset = GrainPreset::SubAngular;
  double roundness = 0.45;        // Wadell roundness, mean over the three principal projections; 1 = sphere
  double elongation = 0.75;       // I / L
  double flatness = 0.75;         // S / I
  int faces = 2000;               // triangles per grain (exactly, for roundness < 1)
  int corners = 16;               // random points whose hull is the core polytope (>= 6)
  double roundness_spread = 0.05; // +- around `roundness`
  double aspect_spread = 0.05;    // +- around `elongation` and `flatness`
  double convexity = 1.0;         // volume / convex hull volume, in [kMinConvexity, 1]; < 1 presses a dent in
};

// The deepest dent the generator makes (one smooth dent, generator.cpp).
inline constexpr double kMinConvexity = 0.8;

// The preset's defaults; change fields afterwards to tune them.
GeneratorSpec preset_spec(GrainPreset preset);

// Throws InputError naming the bad field (roundness outside (0, 1], aspect
// ratios outside (0, 1], faces < 20, corners < 6, negative spreads, convexity
// outside [kMinConvexity, 1]).
void validate(const GeneratorSpec& spec);

// One grain: closed, outward (passes check_mesh), centred at its centroid, in
// its principal frame (x long, y intermediate, z short), of arbitrary size
// (intermediate dimension about 1; scale it afterwards). Reproducible: the same
// spec and generator state give the same mesh, bit for bit.
TriMesh generate_grain(const GeneratorSpec& spec, Rng& rng);

}  // namespace grainlab
