// The built `grainlab grains import | fit-sh | spectrum` commands, a grain
// folder of SH files as a run reads it, and `grains stats` of SH files.
#include "geometry/mass_properties.h"
#include "geometry/mesh_check.h"
#include "geometry/mesh_io.h"
#include "geometry/primitives.h"
#include "geometry/shape_metrics.h"
#include "geometry/test_helpers.h"
#include "file_text.h"
#include "grains/grain_set.h"
#include "grains/sh_grain.h"
#include "grains/sh_test_shapes.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <numbers>
#include <sstream>

namespace grainlab {
namespace {

// Runs `grainlab ARGS`, output to dir/log.txt; returns the exit status.
int grainlab(const test::TempDir& dir, const std::string& args) {
  const std::string cmd = std::string(GRAINLAB_BINARY) + " " + args + " > " + (dir / "log.txt").string() + " 2>&1";
  return std::system(cmd.c_str());
}

// A U-shaped prism (metres) whose centroid lies in its thick base.
TriMesh prism_like_u() {
  TriMesh u = prism_mesh({{0, 0}, {3, 0}, {3, 3}, {2, 3}, {2, 2}, {1, 2}, {1, 3}, {0, 3}}, 1.0);
  for (Vec3& v : u.vertices) v *= 1e-4;
  return u;
}

TEST(ShCommands, ImportWritesMetreMeshesAndRefusesABadFileWritingNothing) {
  test::TempDir dir;
  std::filesystem::create_directories(dir / "in");
  write_sh_file(test::ellipsoid_coefficients(1.0, 0.8, 0.6, 16), dir / "in" / "ellipsoid.dat");
  write_sh_file(test::lumpy_grain(8), dir / "in" / "lumpy.dat");
  ASSERT_EQ(grainlab(dir, "grains import " + (dir / "in").string() + " --faces 1000 --out " + (dir / "out").string()),
            0)
      << test::file_text(dir / "log.txt");
  EXPECT_CONTAINS(test::file_text(dir / "log.txt"), "wrote 2 grains (1000 faces each");
  const TriMesh e = load_mesh(dir / "out" / "ellipsoid.stl");
  EXPECT_EQ(e.faces.size(), 1000u);
  EXPECT_NEAR(mass_properties(e).volume / (4.0 / 3 * std::numbers::pi * 0.48e-9), 1, 0.01);  // mm -> m
  // --d-eq instead of the unit.
  ASSERT_EQ(grainlab(dir, "grains import " + (dir / "in" / "lumpy.dat").string() + " --d-eq 0.5e-3 --out " +
                              (dir / "deq").string()),
            0);
  EXPECT_NEAR(shape_metrics(load_mesh(dir / "deq" / "lumpy.stl")).equivalent_diameter, 0.5e-3, 1e-9);

  // One bad file among good ones: the error names it and its line; no folder is made.
  std::ofstream(dir / "in" / "zz-bad.dat") << "   0   0        1.0000000000        0.0000000000\n   1   1   0.5\n";
  EXPECT_NE(grainlab(dir, "grains import " + (dir / "in").string() + " --out " + (dir / "out2").string()), 0);
  EXPECT_CONTAINS(test::file_text(dir / "log.txt"), "zz-bad.dat:2: expected four numbers");
  EXPECT_FALSE(std::filesystem::exists(dir / "out2"));
}

TEST(ShCommands, StatsMeasureShFilesInTheGivenUnit) {
  test::TempDir dir;
  ShCoefficients ball(0);
  ball.at(0, 0) = std::sqrt(4 * std::numbers::pi) * 500;  // r = 500 um
  write_sh_file(ball, dir / "ball.dat");
  ASSERT_EQ(grainlab(dir, "grains stats " + (dir / "ball.dat").string() + " --unit 1e-6"), 0) << test::file_text(dir / "log.txt");
  const std::string out = test::file_text(dir / "log.txt");
  EXPECT_CONTAINS(out, "ball.dat,");
  EXPECT_CONTAINS(out, "equivalent diameter 1.000 mm");
}

TEST(ShCommands, FitShWritesAFileTheReaderReadsBack) {
  test::TempDir dir;
  const ShCoefficients c = test::lumpy_grain(8, 5, true);
  TriMesh m = sh_mesh(c, 8000, "lumpy");
  for (Vec3& v : m.vertices) v *= 1e-3;  // mm -> m
  write_stl(m, dir / "lumpy.stl");
  ASSERT_EQ(grainlab(dir, "grains fit-sh " + (dir / "lumpy.stl").string() + " --degree 8"), 0) << test::file_text(dir / "log.txt");
  const std::string log = test::file_text(dir / "log.txt");
  EXPECT_CONTAINS(log, "fitted degree 8");
  EXPECT_CONTAINS(log, "RMS radial error");
  const ShCoefficients back = read_sh_file(dir / "lumpy.dat");  // default: the mesh's name, millimetres
  ASSERT_EQ(back.degree, 8);
  for (std::size_t i = 0; i < c.a.size(); ++i) EXPECT_NEAR(std::abs(back.a[i] - c.a[i]), 0, 5e-4) << i;
  // A mesh that is not star-shaped: refused, with the direction.
  write_stl(prism_like_u(), dir / "u.stl");
  EXPECT_NE(grainlab(dir, "grains fit-sh " + (dir / "u.stl").string()), 0);
  EXPECT_CONTAINS(test::file_text(dir / "log.txt"), "not star-shaped about its centroid");
  EXPECT_FALSE(std::filesystem::exists(dir / "u.dat"));
}

TEST(ShCommands, SpectrumOfASetWritesTomlWithAmplitudesAndShapeStatistics) {
  test::TempDir dir;
  ShCoefficients ball(4);
  ball.at(0, 0) = std::sqrt(4 * std::numbers::pi);
  write_sh_file(ball, dir / "ball.dat");
  ShCoefficients egg = ball;  // A_2 = |a_20| / |a_00| = 0.1
  egg.at(2, 0) = 0.1 * ball.at(0, 0);
  write_sh_file(egg, dir / "egg.dat");
  ASSERT_EQ(grainlab(dir, "grains spectrum " + (dir / "ball.dat").string() + " " + (dir / "egg.dat").string() +
                              " --out " + (dir / "sand.toml").string()),
            0)
      << test::file_text(dir / "log.txt");
  const std::string toml = test::file_text(dir / "sand.toml");
  EXPECT_CONTAINS(toml, "grains = 2\ndegree = 4\n");
  EXPECT_CONTAINS(toml, "mean = [1, 0, 0.05, 0, 0]");
  EXPECT_CONTAINS(toml, "std = [0, 0, 0.0707107, 0, 0]");
  for (const char* key : {"equivalent_diameter_m = {", "roundness = {", "sphericity = {", "elongation = {",
                          "flatness = {", "convexity = {"}) {
    EXPECT_CONTAINS(toml, key);
  }
  EXPECT_CONTAINS(test::file_text(dir / "log.txt"), "A_n/A_0 at n = 2, 5, 10, 20: 0.0500, -, -, -");
  // Degrees above --max-degree are left out, of the spectrum and of the meshes.
  ASSERT_EQ(grainlab(dir, "grains spectrum " + (dir / "egg.dat").string() + " --max-degree 1 --out " +
                              (dir / "smooth.toml").string()),
            0)
      << test::file_text(dir / "log.txt");
  EXPECT_CONTAINS(test::file_text(dir / "smooth.toml"), "degree = 1\n");
  EXPECT_CONTAINS(test::file_text(dir / "smooth.toml"), "sphericity = { mean = 0.99");  // the egg's a_20 is gone: a ball
}

TEST(ShCommands, AGrainFolderOfShFilesIsAGrainSet) {
  test::TempDir dir;
  write_sh_file(test::ellipsoid_coefficients(1.0, 0.8, 0.6, 12), dir / "a.dat");
  write_sh_file(test::lumpy_grain(8), dir / "b.dat");
  const GrainSet set = import_grain_set(dir.path, 200, SieveRange{0.7e-3, 0.8e-3});
  ASSERT_EQ(set.meshes.size(), 2u);
  EXPECT_EQ(set.names[0], "a");
  for (const TriMesh& m : set.meshes) {
    EXPECT_EQ(m.faces.size(), 200u);
    EXPECT_LT(mass_properties(m).centroid.norm(), 1e-12);
    const double size = size_of(m);
    EXPECT_TRUE(size > 0.7e-3 && size < 0.8e-3) << size;
  }
}

}  // namespace
}  // namespace grainlab

namespace grainlab {
namespace {

TEST(ShCommands, GenerateFromASpectrumWritesTheSameGrainsForTheSameSeedAndRefusesBadUse) {
  test::TempDir dir;
  // A spectrum of two measured grains, as `grains spectrum` writes it.
  write_sh_file(test::lumpy_grain(6), dir / "a.dat");
  write_sh_file(test::lumpy_grain(6, 9), dir / "b.dat");
  const std::string spectrum = (dir / "sand.toml").string();
  ASSERT_EQ(grainlab(dir, "grains spectrum " + (dir / "a.dat").string() + " " + (dir / "b.dat").string() +
                              " --faces 500 --out " + spectrum),
            0)
      << test::file_text(dir / "log.txt");
  const std::string args = "grains generate --spectrum " + spectrum + " --count 3 --faces 300 --seed 4 --out ";
  ASSERT_EQ(grainlab(dir, args + (dir / "one").string()), 0) << test::file_text(dir / "log.txt");
  const std::string log = test::file_text(dir / "log.txt");
  EXPECT_CONTAINS(log, "wrote 3 grains of degree 6 drawn from");
  EXPECT_CONTAINS(log, "roundness");
  ASSERT_EQ(grainlab(dir, args + (dir / "two").string()), 0);
  for (const char* f : {"sh-0001.stl", "sh-0002.stl", "sh-0003.stl"}) {
    EXPECT_EQ(test::file_text(dir / "one" / f), test::file_text(dir / "two" / f)) << f;
    EXPECT_EQ(load_mesh(dir / "one" / f).faces.size(), 300u);
  }
  // The file holds the set's shape model, which generate uses unless told otherwise.
  EXPECT_CONTAINS(test::file_text(dir / "sand.toml"), "[model]\n");
  EXPECT_CONTAINS(log, "by the shape-model method");
  ASSERT_EQ(grainlab(dir, args + (dir / "phases").string() + " --method random-phase"), 0);
  EXPECT_CONTAINS(test::file_text(dir / "log.txt"), "by the random-phase method");
  EXPECT_NE(test::file_text(dir / "one" / "sh-0001.stl"), test::file_text(dir / "phases" / "sh-0001.stl"));
  // Without a model (an older file), random-phase is the default and shape-model is refused.
  const std::string plain = (dir / "plain.toml").string();
  ASSERT_EQ(grainlab(dir, "grains spectrum " + (dir / "a.dat").string() + " " + (dir / "b.dat").string() +
                              " --faces 500 --model-degree -1 --out " + plain),
            0);
  EXPECT_EQ(test::file_text(plain).find("[model]"), std::string::npos);
  const std::string plain_args = "grains generate --spectrum " + plain + " --count 3 --faces 300 --seed 4 --out ";
  ASSERT_EQ(grainlab(dir, plain_args + (dir / "old").string()), 0);
  EXPECT_CONTAINS(test::file_text(dir / "log.txt"), "by the random-phase method");
  EXPECT_EQ(test::file_text(dir / "old" / "sh-0001.stl"), test::file_text(dir / "phases" / "sh-0001.stl"));
  EXPECT_NE(grainlab(dir, plain_args + (dir / "four").string() + " --method shape-model"), 0);
  EXPECT_CONTAINS(test::file_text(dir / "log.txt"), "needs a spectrum with a [model]");
  EXPECT_NE(grainlab(dir, args + (dir / "three").string() + " --preset rounded"), 0);
  EXPECT_CONTAINS(test::file_text(dir / "log.txt"), "excludes");
  EXPECT_NE(grainlab(dir, args + (dir / "three").string() + " --roundness 0.5"), 0);
  EXPECT_NE(grainlab(dir, "grains generate --spectrum " + (dir / "none.toml").string() + " --out " +
                              (dir / "three").string()),
            0);
  EXPECT_CONTAINS(test::file_text(dir / "log.txt"), "does not exist");
  EXPECT_FALSE(std::filesystem::exists(dir / "three"));
  EXPECT_NE(grainlab(dir, "grains generate --out " + (dir / "three").string()), 0);
  EXPECT_CONTAINS(test::file_text(dir / "log.txt"), "needs --preset NAME or --spectrum SAND.toml");
}

}  // namespace
}  // namespace grainlab
