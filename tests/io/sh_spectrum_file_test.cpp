// Spectrum files: a file in `grains spectrum`'s layout read back, and every
// kind of bad file refused with the file, line and key.
#include "io/sh_spectrum_file.h"

#include "geometry/test_helpers.h"

#include <gtest/gtest.h>

#include <fstream>

namespace grainlab {
namespace {

const std::string kGood =
    "# A sand's shape\n"
    "[set]\ngrains = 2\ndegree = 3\nunit_m = 0.001\n\n"
    "[spectrum]\nmean = [1, 0.01, 0.2, 0.05]\nstd = [0, 0.005, 0.07, 0.02]\n\n"
    "[shape]\n"
    "equivalent_diameter_m = { mean = 0.00175, std = 0.0009, min = 0.001, max = 0.004 }  # m\n"
    "roundness = { mean = 0.464, std = 0.04, min = 0.4, max = 0.5 }\n"
    "convexity = { mean = 0.885, std = 0.03, min = 0.8, max = 0.95 }\n";

std::filesystem::path write(const test::TempDir& dir, const std::string& text) {
  const auto path = dir / "sand.toml";
  std::ofstream(path) << text;
  return path;
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  text.replace(text.find(from), from.size(), to);
  return text;
}

TEST(ShSpectrumFile, ReadsWhatGrainsSpectrumWrites) {
  test::TempDir dir;
  const ShSpectrumFile f = read_sh_spectrum(write(dir, kGood));
  EXPECT_EQ(f.spectrum.degree(), 3);
  EXPECT_EQ(f.spectrum.mean, (std::vector<double>{1, 0.01, 0.2, 0.05}));
  EXPECT_EQ(f.spectrum.std, (std::vector<double>{0, 0.005, 0.07, 0.02}));
  EXPECT_EQ(f.spectrum.d_eq_mean, 0.00175);
  EXPECT_EQ(f.spectrum.d_eq_max, 0.004);
  ASSERT_EQ(f.shape_means.size(), 2u);  // the file gives two of the five
  EXPECT_EQ(f.shape_means[0], std::make_pair(std::string("roundness"), 0.464));
  EXPECT_EQ(f.shape_means[1].first, "convexity");
}

TEST(ShSpectrumFile, RefusesBadFilesNamingFileLineAndKey) {
  test::TempDir dir;
  const auto error = [&](const std::string& text) {
    return test::input_error_of([&] { read_sh_spectrum(write(dir, text)); });
  };
  EXPECT_CONTAINS(error(replaced(kGood, "std = [0, 0.005, 0.07, 0.02]\n", "")),
                  "missing key `std` in [spectrum]; write it with `grainlab grains spectrum");
  EXPECT_CONTAINS(error(replaced(kGood, "degree = 3", "")), "missing key `degree` in [set]");
  EXPECT_CONTAINS(error(replaced(kGood, "min = 0.001, ", "")), "missing key `equivalent_diameter_m.min` in [shape]");
  EXPECT_CONTAINS(error(replaced(kGood, "0.07, 0.02]", "-0.07, 0.02]")),
                  "sand.toml:9: [spectrum] std[2] = -0.07 is negative");
  EXPECT_CONTAINS(error(replaced(kGood, "degree = 3", "degree = 4")),
                  "sand.toml:8: [spectrum] mean has 4 values but [set] degree = 4 needs 5");
  EXPECT_CONTAINS(error(replaced(kGood, "degree = 3", "degree = 2.5")), "sand.toml:4: [set] degree must be an integer");
  EXPECT_CONTAINS(error(replaced(kGood, "0.2, 0.05]", "\"a\", 0.05]")), "[spectrum] mean[2] must be a number, got a string");
  EXPECT_CONTAINS(error(replaced(kGood, "mean = 0.00175", "mean = 0.0005")), "0 < min <= mean <= max");
  EXPECT_CONTAINS(error(replaced(kGood, "[spectrum]", "[spectrum")), "sand.toml:7: TOML syntax error");
  EXPECT_CONTAINS(test::input_error_of([&] { read_sh_spectrum(dir / "none.toml"); }),
                  "spectrum file '" + (dir / "none.toml").string() + "' does not exist");
}

// A model of degree 1 with two components (unit vectors of 4 numbers).
ShShapeModel small_model() {
  ShShapeModel m;
  m.degree = 1;
  m.mean = {1, 0.01, -0.02, 0.003};
  m.components = {{0, 0.6, 0.8, 0}, {0, 0, 0, 1}};
  m.sigma = {0.05, 0.01};
  m.residual = {0, 0.002};
  return m;
}

TEST(ShSpectrumFile, ModelRoundTripsThroughTheFile) {
  test::TempDir dir;
  const ShShapeModel m = small_model();
  const ShSpectrumFile f = read_sh_spectrum(write(dir, kGood + sh_model_toml(m)));
  const ShShapeModel& r = f.spectrum.model;
  EXPECT_EQ(r.degree, 1);
  EXPECT_EQ(r.mean, m.mean);
  EXPECT_EQ(r.sigma, m.sigma);
  EXPECT_EQ(r.residual, m.residual);
  EXPECT_EQ(r.components, m.components);
  EXPECT_TRUE(read_sh_spectrum(write(dir, kGood)).spectrum.model.empty());  // a file without [model]
  EXPECT_EQ(sh_model_toml(ShShapeModel{}), "");
}

TEST(ShSpectrumFile, RefusesBadModelsNamingFileLineAndKey) {
  test::TempDir dir;
  const std::string good = kGood + sh_model_toml(small_model());
  const auto error = [&](const std::string& text) {
    return test::input_error_of([&] { read_sh_spectrum(write(dir, text)); });
  };
  EXPECT_CONTAINS(error(replaced(good, "mean = [1, 0.01, -0.02, 0.003]", "mean = [1, 0.01, -0.02]")),
                  "sand.toml:22: [model] mean has 3 values but [model] degree = 1");
  EXPECT_CONTAINS(error(replaced(good, "sigma = [0.05, 0.01]", "sigma = [0.05, -0.01]")),
                  "[model] sigma[1] = -0.01 is negative");
  EXPECT_CONTAINS(error(replaced(good, "[0, 0.6, 0.8, 0]", "[0, 0.6, 0.9, 0]")),
                  "sand.toml:21: [model]: shape model component 0 has length");
  EXPECT_CONTAINS(error(replaced(good, "sigma = [0.05, 0.01]", "sigma = [0.05]")),
                  "[model] components must be an array of 1 arrays");
  EXPECT_CONTAINS(error(replaced(good, "residual = [0, 0.002]\n", "")), "missing key `residual` in [model]");
  EXPECT_CONTAINS(error(replaced(good, "degree = 1", "degree = 4")), "[model] degree must be an integer in 0..3");
  EXPECT_CONTAINS(error(replaced(good, "[0, 0, 0, 1]", "[0, 0, nan, 1]")), "is not a finite number");
}

}  // namespace
}  // namespace grainlab
