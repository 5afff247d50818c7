// Grain sets: sizes within the sieve range, principal frame, glass beads as
// spheres, and import from a folder of mesh files.
#include "grains/grain_set.h"

#include "geometry/mass_properties.h"
#include "geometry/mesh_check.h"
#include "geometry/mesh_io.h"
#include "geometry/primitives.h"
#include "geometry/shape_metrics.h"
#include "geometry/test_helpers.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace grainlab {
namespace {

TEST(GrainSet, SizesSpreadOverTheSieveRange) {
  const SieveRange sieve;  // 0.707-0.841 mm
  const GrainSet set = generate_grain_set(GrainPreset::SubAngular, 20, 3, sieve);
  ASSERT_EQ(set.meshes.size(), 20u);
  ASSERT_EQ(set.names.size(), 20u);
  EXPECT_FALSE(set.spheres);
  std::vector<double> d;
  for (const TriMesh& m : set.meshes) d.push_back(size_of(m));
  std::sort(d.begin(), d.end());
  const double w = (sieve.d_max - sieve.d_min) / 20;
  for (int k = 0; k < 20; ++k) {  // one size in each twentieth of the range
    EXPECT_GE(d[k], sieve.d_min + k * w - 1e-12);
    EXPECT_LE(d[k], sieve.d_min + (k + 1) * w + 1e-12);
  }
}

TEST(GrainSet, MeshesAreCentredInTheirPrincipalFrame) {
  const GrainSet set = generate_grain_set(GrainPreset::Angular, 3, 9);
  for (const TriMesh& m : set.meshes) {
    const PrincipalFrame f = principal_frame(m);
    EXPECT_LT(f.centroid.norm(), 1e-12);
    EXPECT_NEAR(std::abs(f.axes(0, 0)), 1.0, 1e-6);  // long axis along x
    EXPECT_NEAR(std::abs(f.axes(1, 1)), 1.0, 1e-6);  // intermediate along y
  }
}

TEST(GrainSet, GlassBeadsAreSpheresOfSieveDiameter) {
  const GrainSet set = generate_grain_set(GrainPreset::GlassBeads, 5, 1);
  EXPECT_TRUE(set.spheres);
  for (const TriMesh& m : set.meshes) {
    const ShapeMetrics s = shape_metrics(m);
    EXPECT_NEAR(s.sphericity, 1.0, 0.01);
    EXPECT_GE(s.intermediate_axis, 0.707e-3 - 1e-12);
    EXPECT_LE(s.intermediate_axis, 0.841e-3 + 1e-12);
  }
}

TEST(GrainSet, RejectsBadSieveAndCount) {
  EXPECT_THROW(generate_grain_set(GrainPreset::Rounded, 3, 1, SieveRange{1e-3, 0.5e-3}), InputError);
  EXPECT_THROW(generate_grain_set(GrainPreset::Rounded, 0, 1), InputError);
}

TEST(GrainSet, ImportsAFolderSimplifiedScaledAndCentred) {
  test::TempDir dir;
  // Three "scanned" grains in millimetres, finer than the budget, out of their frame.
  TriMesh a = ellipsoid_mesh(2.0, 1.2, 0.8, 5);  // 20480 faces
  for (Vec3& v : a.vertices) v += Vec3(5, -3, 1);
  write_stl(a, dir / "b_grain.stl");
  write_obj(icosphere(0.5, 5), dir / "a_grain.obj");
  write_stl(box_mesh(1.0, 0.8, 0.6), dir / "c_grain.STL");
  write_obj(box_mesh(1, 1, 1), dir / "notes.txt");  // ignored: not a mesh extension
  const SieveRange sieve;
  const GrainSet set = import_grain_set(dir.path, 2000, sieve);
  ASSERT_EQ(set.meshes.size(), 3u);
  EXPECT_EQ(set.names, (std::vector<std::string>{"a_grain", "b_grain", "c_grain"}));
  EXPECT_TRUE(set.notes.empty());
  for (const TriMesh& m : set.meshes) {
    EXPECT_TRUE(check_mesh(m).ok());
    EXPECT_LE(m.faces.size(), 2000u);
    EXPECT_LT(principal_frame(m).centroid.norm(), 1e-9);
    EXPECT_GE(size_of(m), sieve.d_min);
    EXPECT_LE(size_of(m), sieve.d_max);
  }
  // Size order kept: the sphere (I = 1 mm) is the smallest, the ellipsoid (I = 2.4) the largest.
  EXPECT_LT(size_of(set.meshes[0]), size_of(set.meshes[2]));
  EXPECT_LT(size_of(set.meshes[2]), size_of(set.meshes[1]));
  // The simplified ellipsoid keeps its shape: elongation 1.2 / 2.
  EXPECT_NEAR(shape_metrics(set.meshes[1]).elongation, 0.6, 0.02);
}

TEST(GrainSet, ImportRefusesAnEmptyOrMissingFolder) {
  test::TempDir dir;
  EXPECT_CONTAINS(test::input_error_of([&] { import_grain_set(dir.path, 2000, {}); }), "no .stl");
  EXPECT_CONTAINS(test::input_error_of([&] { import_grain_set(dir / "nope", 2000, {}); }), "does not exist");
}

}  // namespace
}  // namespace grainlab

namespace grainlab {
namespace {

// STL stores single precision: sharp, coarse grains must stay valid when their
// coordinates are rounded to float. (read_mesh's assimp vertex joining merges
// vertices a few micrometres apart in metre-unit files: see docs/grains.md.)
TEST(GrainSet, AngularGrainsSurviveSinglePrecision) {
  for (int faces : {200, 500, 2000}) {
    const GrainSet set = generate_grain_set(GrainPreset::Angular, 6, 7, {}, faces);
    for (std::size_t i = 0; i < set.meshes.size(); ++i) {
      TriMesh f = set.meshes[i];
      for (Vec3& v : f.vertices) v = v.cast<float>().cast<double>();
      const MeshCheck c = check_mesh(f);
      EXPECT_TRUE(c.ok() && c.duplicate_vertices == 0) << set.names[i] << " at " << faces << ": " << c.describe();
    }
  }
}

}  // namespace
}  // namespace grainlab
