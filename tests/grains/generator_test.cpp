// Generated grains: valid meshes, roundness bands in the paper's order, the
// requested face count and shape, reproducible from the seed.
#include "grains/generator.h"

#include "core/error.h"
#include "geometry/mass_properties.h"
#include "geometry/mesh_check.h"
#include "geometry/shape_metrics.h"
#include "grains/grain_set.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstring>

namespace grainlab {
namespace {

struct Band {
  double mean = 0, min = 1, max = 0;
};

// 30 grains per preset, as the issue asks; generated once for all tests here.
const std::vector<GrainSet>& preset_sets() {
  static const std::vector<GrainSet> sets = [] {
    std::vector<GrainSet> v;
    for (GrainPreset p : {GrainPreset::GlassBeads, GrainPreset::Rounded, GrainPreset::SubAngular,
                          GrainPreset::Angular}) {
      v.push_back(generate_grain_set(p, 30, 11));
    }
    return v;
  }();
  return sets;
}

TEST(Generator, PresetsLandInSeparateRoundnessBandsInThePapersOrder) {
  std::vector<Band> bands;
  for (const GrainSet& set : preset_sets()) {
    Band b;
    for (const TriMesh& m : set.meshes) {
      const double r = shape_metrics(m).roundness;
      b.mean += r / set.meshes.size();
      b.min = std::min(b.min, r);
      b.max = std::max(b.max, r);
    }
    std::printf("%s: roundness mean %.3f range [%.3f, %.3f]\n", set.names[0].c_str(), b.mean, b.min, b.max);
    bands.push_back(b);
  }
  // glass beads > rounded > sub-angular > angular, bands not overlapping.
  for (std::size_t k = 0; k + 1 < bands.size(); ++k) {
    EXPECT_GT(bands[k].min, bands[k + 1].max) << "preset " << k << " overlaps preset " << k + 1;
  }
  EXPECT_GT(bands[0].mean, 0.9);
  for (std::size_t k = 1; k < bands.size(); ++k) {
    const GeneratorSpec spec = preset_spec(static_cast<GrainPreset>(k));
    EXPECT_NEAR(bands[k].mean, spec.roundness, 0.05) << grain_preset_name(spec.preset);
  }
}

TEST(Generator, EveryMeshIsValidWithVolumeMatchingMassProperties) {
  for (const GrainSet& set : preset_sets()) {
    ASSERT_EQ(set.meshes.size(), 30u);
    for (std::size_t i = 0; i < set.meshes.size(); ++i) {
      const TriMesh& m = set.meshes[i];
      const MeshCheck c = check_mesh(m);
      ASSERT_TRUE(c.ok()) << set.names[i] << ": " << c.describe();
      EXPECT_EQ(m.faces.size(), 2000u) << set.names[i];
      const MassProperties mp = mass_properties(m);
      EXPECT_GT(mp.volume, 0);
      EXPECT_NEAR(shape_metrics(m).volume, mp.volume, 1e-12 * mp.volume);
      EXPECT_NEAR(c.signed_volume, mp.volume, 1e-9 * mp.volume);
      EXPECT_LT(mp.centroid.norm(), 1e-9 * size_of(m)) << "centred";
    }
  }
}

TEST(Generator, AspectRatiosFollowTheSpec) {
  GeneratorSpec spec = preset_spec(GrainPreset::SubAngular);
  spec.elongation = 0.6;
  spec.flatness = 0.7;
  spec.aspect_spread = 0;
  Rng rng(5);
  double e = 0, f = 0;
  for (int i = 0; i < 10; ++i) {
    const ShapeMetrics s = shape_metrics(generate_grain(spec, rng));
    e += s.elongation / 10;
    f += s.flatness / 10;
  }
  EXPECT_NEAR(e, 0.6, 0.06);
  EXPECT_NEAR(f, 0.7, 0.07);
}

TEST(Generator, FaceBudgetIsMet) {
  GeneratorSpec spec = preset_spec(GrainPreset::Angular);
  for (int faces : {200, 1000, 4000}) {
    spec.faces = faces;
    Rng rng(1);
    const TriMesh m = generate_grain(spec, rng);
    EXPECT_EQ(static_cast<int>(m.faces.size()), faces);
    EXPECT_TRUE(check_mesh(m).ok());
  }
}

// A grain of few faces is a coarse tessellation of the body a fine one
// tessellates (the same core and corner radius): its elongation, flatness
// and sphericity are the 1000-face grain's, its volume a few per cent less
// (a tessellation inside the body). Until 2026-12-04 the corner radius was
// chased on the coarse mesh, whose measured roundness cannot reach 0.70, and
// 200-face rounded grains came out as balls (elongation 0.96, flatness 0.97,
// sphericity 0.99 against 0.82, 0.85, 0.97).
TEST(Generator, AGrainOfFewFacesIsTheSameBodyTessellatedCoarser) {
  for (GrainPreset p : {GrainPreset::Rounded, GrainPreset::SubAngular, GrainPreset::Angular}) {
    GeneratorSpec spec = preset_spec(p);
    for (std::uint64_t seed : {1, 2, 3, 4}) {
      spec.faces = 1000;
      Rng fine_rng(seed);
      const TriMesh fine = generate_grain(spec, fine_rng);
      spec.faces = 200;
      Rng coarse_rng(seed);
      const TriMesh coarse = generate_grain(spec, coarse_rng);
      const ShapeMetrics f = shape_metrics(fine), c = shape_metrics(coarse);
      const std::string what = std::string(grain_preset_name(p)) + " seed " + std::to_string(seed);
      EXPECT_NEAR(c.elongation, f.elongation, 0.03) << what;
      EXPECT_NEAR(c.flatness, f.flatness, 0.03) << what;
      EXPECT_NEAR(c.sphericity, f.sphericity, 0.02) << what;
      const double v_fine = mass_properties(fine).volume, v_coarse = mass_properties(coarse).volume;
      EXPECT_LT(v_coarse, v_fine) << what;
      EXPECT_GT(v_coarse, 0.95 * v_fine) << what;
    }
  }
}

TEST(Generator, SameSeedSameBitsDifferentSeedDifferentGrains) {
  const GrainSet a = generate_grain_set(GrainPreset::Angular, 4, 42);
  const GrainSet b = generate_grain_set(GrainPreset::Angular, 4, 42);
  const GrainSet c = generate_grain_set(GrainPreset::Angular, 4, 43);
  ASSERT_EQ(a.meshes.size(), b.meshes.size());
  for (std::size_t i = 0; i < a.meshes.size(); ++i) {
    EXPECT_EQ(a.meshes[i].faces, b.meshes[i].faces);
    ASSERT_EQ(a.meshes[i].vertices.size(), b.meshes[i].vertices.size());
    EXPECT_EQ(std::memcmp(a.meshes[i].vertices.data(), b.meshes[i].vertices.data(),
                          a.meshes[i].vertices.size() * sizeof(Vec3)),
              0)
        << "grain " << i << " differs between two runs with the same seed";
  }
  EXPECT_NE(a.meshes[0].vertices[0], c.meshes[0].vertices[0]);
}

TEST(Generator, PresetNamesRoundTripAndBadNamesAreListed) {
  for (GrainPreset p : {GrainPreset::GlassBeads, GrainPreset::Rounded, GrainPreset::SubAngular,
                        GrainPreset::Angular}) {
    EXPECT_EQ(parse_grain_preset(grain_preset_name(p)), p);
  }
  try {
    parse_grain_preset("subangular");
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("sub-angular"), std::string::npos) << e.what();
  }
}

TEST(Generator, RejectsImpossibleSpecs) {
  GeneratorSpec spec = preset_spec(GrainPreset::Rounded);
  spec.roundness = 1.5;
  Rng rng(1);
  EXPECT_THROW(generate_grain(spec, rng), InputError);
  spec = preset_spec(GrainPreset::Rounded);
  spec.elongation = 0;
  EXPECT_THROW(generate_grain(spec, rng), InputError);
}

TEST(Generator, ConvexityControlPressesTwoDentsToTheTarget) {
  // Convexity V / V_hull within 0.002 of the target (the generator bisects
  // to 1e-4; the metric recomputes the hull of the rescaled, rotated mesh),
  // a valid closed mesh, unit intermediate dimension as convex grains.
  for (GrainPreset preset : {GrainPreset::Rounded, GrainPreset::SubAngular, GrainPreset::GlassBeads}) {
    for (double convexity : {0.97, 0.9, 0.8}) {
      SCOPED_TRACE(std::string(grain_preset_name(preset)) + " " + std::to_string(convexity));
      GeneratorSpec spec = preset_spec(preset);
      spec.faces = 600;
      spec.convexity = convexity;
      Rng rng(7);
      const TriMesh m = generate_grain(spec, rng);
      EXPECT_TRUE(check_mesh(m).ok()) << check_mesh(m).describe();
      const ShapeMetrics s = shape_metrics(m);
      EXPECT_NEAR(s.convexity, convexity, 0.002);
      EXPECT_NEAR(s.intermediate_axis, 1.0, 1e-9);  // unit intermediate dimension, as convex grains
    }
  }
  // Convex grains draw nothing more: convexity 1 is the same bits as before.
  GeneratorSpec spec = preset_spec(GrainPreset::SubAngular);
  spec.faces = 300;
  Rng a(3), b(3);
  const TriMesh convex = generate_grain(spec, a);
  spec.convexity = 1.0;
  EXPECT_EQ(generate_grain(spec, b).vertices, convex.vertices);
  spec.convexity = 0.75;  // below kMinConvexity
  EXPECT_THROW(validate(spec), InputError);
  spec.convexity = 1.01;
  EXPECT_THROW(validate(spec), InputError);
}

}  // namespace
}  // namespace grainlab
