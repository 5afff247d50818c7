// A sand's spectrum file (`grainlab grains spectrum --out SAND.toml`) read
// back for `grainlab grains generate --spectrum`. The file (TOML):
//   [set]       grains, degree = N, unit_m
//   [spectrum]  mean = [...], std = [...]: N + 1 numbers each, A_n / A_0 for
//               n = 0..N (mean[0] = 1)
//   [shape]     equivalent_diameter_m = { mean, std, min, max } (m), and the
//               same table for roundness, sphericity, elongation, flatness,
//               convexity (optional here: only reported beside a generated set)
//   [model]     optional, the set's shape model (grains/sh_shape_model.h):
//               degree = K (<= [set] degree), mean = [(K + 1)^2 numbers],
//               sigma = [k numbers], residual = [K + 1 numbers],
//               components = [[(K + 1)^2 numbers], ...] (k arrays)
#pragma once

#include "grains/sh_generator.h"

#include <filesystem>
#include <string>
#include <vector>

namespace grainlab {

struct ShSpectrumFile {
  ShSpectrum spectrum;
  // [shape] means of the measured set, in the order roundness, sphericity,
  // elongation, flatness, convexity (those the file gives).
  std::vector<std::pair<std::string, double>> shape_means;
};

// The shape measures a spectrum file may hold besides d_eq, in file order.
inline constexpr const char* kSpectrumShapeKeys[] = {"roundness", "sphericity", "elongation", "flatness",
                                                     "convexity"};

// Reads a spectrum file. Throws InputError naming the file, the line and the
// key for a syntax error, a missing key ([set] degree, [spectrum] mean and
// std, [shape] equivalent_diameter_m's mean, std, min and max), a value of
// the wrong type, arrays whose length is not degree + 1, a negative or
// non-finite amplitude, or d_eq values that are not 0 < min <= mean <= max.
// A [model] with a wrong length, a component not of unit length or a
// negative spread is refused the same way.
ShSpectrumFile read_sh_spectrum(const std::filesystem::path& path);

// The [model] table of a spectrum file for `model` (with its header line and
// a comment saying what it holds); "" for an empty model.
std::string sh_model_toml(const ShShapeModel& model);

}  // namespace grainlab
