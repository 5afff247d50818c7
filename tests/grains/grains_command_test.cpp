// The built `grainlab grains` command: generate writes one STL per grain, stats
// prints a CSV with a header and a roundness column, and a summary on stderr.
#include "geometry/test_helpers.h"
#include "file_text.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace grainlab {
namespace {

TEST(GrainsCommand, GenerateThenStats) {
  test::TempDir dir;
  const std::string bin = GRAINLAB_BINARY;
  const std::string out = (dir / "set").string();
  const std::string gen = bin + " grains generate --preset angular --count 3 --seed 7 --out " + out +
                          " > " + (dir / "gen.txt").string() + " 2>&1";
  ASSERT_EQ(std::system(gen.c_str()), 0) << test::file_text(dir / "gen.txt");
  for (const char* f : {"angular-0001.stl", "angular-0002.stl", "angular-0003.stl"}) {
    EXPECT_TRUE(std::filesystem::exists(std::filesystem::path(out) / f)) << f;
  }
  const std::string stats = bin + " grains stats " + out + " > " + (dir / "stats.csv").string() + " 2> " +
                            (dir / "stats.err").string();
  ASSERT_EQ(std::system(stats.c_str()), 0) << test::file_text(dir / "stats.err");
  const std::string csv = test::file_text(dir / "stats.csv");
  std::istringstream lines(csv);
  std::string header;
  std::getline(lines, header);
  EXPECT_CONTAINS(header, "file,volume_m3,");
  EXPECT_CONTAINS(header, ",roundness,simulated_as,pieces,collision_excess");
  int rows = 0;
  for (std::string line; std::getline(lines, line);) rows += !line.empty();
  EXPECT_EQ(rows, 3);
  const std::string err = test::file_text(dir / "stats.err");
  EXPECT_CONTAINS(err, "3 grains");
  EXPECT_CONTAINS(err, "roundness");
  EXPECT_CONTAINS(err, "simulated as convex pieces: 0 of 3");  // convex grains: their hulls
}

TEST(GrainsCommand, UnknownPresetIsRefused) {
  test::TempDir dir;
  const std::string cmd = std::string(GRAINLAB_BINARY) + " grains generate --preset cubes --out " +
                          (dir / "x").string() + " > /dev/null 2>&1";
  EXPECT_NE(std::system(cmd.c_str()), 0);
}

TEST(GrainsCommand, ConvexityDentsTheGrainsAndStatsMeasureIt) {
  test::TempDir dir;
  const std::string bin = GRAINLAB_BINARY;
  const std::string out = (dir / "dented").string();
  const std::string gen = bin + " grains generate --preset sub-angular --count 2 --faces 400 --convexity 0.9 --out " +
                          out + " > " + (dir / "gen.txt").string() + " 2>&1";
  ASSERT_EQ(std::system(gen.c_str()), 0) << test::file_text(dir / "gen.txt");
  EXPECT_CONTAINS(test::file_text(dir / "gen.txt"), "convexity 0.90");  // the set's summary line
  const std::string stats = bin + " grains stats " + out + " > " + (dir / "stats.csv").string() + " 2>&1";
  ASSERT_EQ(std::system(stats.c_str()), 0) << test::file_text(dir / "stats.csv");
  EXPECT_CONTAINS(test::file_text(dir / "stats.csv"), "convexity 0.90");
  // Below convexity 0.98, a run collides them as convex pieces ("auto").
  EXPECT_CONTAINS(test::file_text(dir / "stats.csv"), ",pieces,");
  EXPECT_CONTAINS(test::file_text(dir / "stats.csv"), "simulated as convex pieces: 2 of 2");
  // Below what two dents reach: refused, nothing written.
  const std::string deep = bin + " grains generate --preset sub-angular --convexity 0.5 --out " +
                           (dir / "deep").string() + " > " + (dir / "deep.txt").string() + " 2>&1";
  EXPECT_NE(std::system(deep.c_str()), 0);
  EXPECT_CONTAINS(test::file_text(dir / "deep.txt"), "--convexity");
  EXPECT_FALSE(std::filesystem::exists(dir / "deep"));
}

}  // namespace
}  // namespace grainlab
