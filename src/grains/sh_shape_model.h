// A statistical shape model of a sand's spherical-harmonic (SH) grains, after
// Zhou and Wang (2017) and Wei et al. (2018): the grains are turned into
// their principal frames (long, intermediate, short axis on x, y, z; each
// axis's sign fixed by the grain's third moment along it), their
// coefficients of degree <= K divided by a_00, and the set's mean and main
// components of variation (principal component analysis, PCA) kept. A new
// grain is the mean plus each kept component times a normal score of that
// component's spread; the variance the kept components leave, and the
// degrees above K, are drawn with random phases from the set's per-degree
// amplitudes (sh_generator.h). Derivation at the top of sh_shape_model.cpp.
#pragma once

#include "core/rng.h"
#include "geometry/spherical_harmonics.h"

#include <vector>

namespace grainlab {

// What `grainlab grains spectrum` fits by default: degrees <= K and the
// number of principal components kept (chosen by measurement, docs/grains.md).
inline constexpr int kDefaultModelDegree = 30;
inline constexpr int kDefaultModelComponents = 15;

// Coefficients of degree <= K as a real vector of sh_count(K) numbers, at
// sh_index(n, m): x_{n,0} = a_n0, x_{n,m} = sqrt 2 Re a_nm and x_{n,-m} =
// sqrt 2 Im a_nm for m > 0 (orthonormal: the sum of squares of degree n is
// A_n^2 for a real r).
std::vector<double> sh_real_vector(const ShCoefficients& c, int degree);
ShCoefficients sh_from_real_vector(const std::vector<double>& x, int degree);

// `c` turned into its principal frame: r'(u) = r(Q u) with Q's columns the
// long, intermediate and short principal axes of its mesh (`faces`
// triangles), each axis's sign chosen so that the third moment of the mesh's
// vertices along it, about the centroid, is >= 0 (Q may be a reflection).
// About the same origin; exact to rounding (the rotated r is projected on a
// quadrature exact for its degree).
ShCoefficients sh_aligned(const ShCoefficients& c, int faces);

// The model. components[i] are unit vectors (orthogonal) of sh_count(degree)
// numbers; sigma[i] the standard deviation of the grains' scores along them
// (descending); residual[n] (n = 0..degree) the root-mean-square over the
// grains of A_n / a_00 of what the kept components leave (0 when all are kept).
struct ShShapeModel {
  int degree = -1;  // K; -1: no model
  std::vector<double> mean;
  std::vector<std::vector<double>> components;
  std::vector<double> sigma;
  std::vector<double> residual;

  bool empty() const { return degree < 0; }
};

// Throws InputError naming the bad value: lengths that do not match the
// degree, mean[0] (the a_00 / a_00 of the mean) not 1, a sigma or residual
// negative or not finite, components not of unit length.
void validate(const ShShapeModel& model);

// The model of `grains` (any poses, any sizes; each of degree >= `degree`):
// aligned with sh_aligned (`faces` triangles), normalised by a_00, PCA of
// their coefficients of degree <= `degree`, keeping the first `components`
// components (at most grains - 1; those of zero spread dropped).
ShShapeModel fit_sh_shape_model(const std::vector<ShCoefficients>& grains, int degree, int components, int faces);

// One draw of the model's degrees (a_00 about 1): the mean plus sum_i z_i
// sigma_i components_i with z_i standard normal, then per degree n >= 1 a
// random-phase term of amplitude residual[n] (set_random_degree's
// direction). Degree `out_degree` >= model degree; higher degrees left 0.
ShCoefficients draw_from_model(const ShShapeModel& model, int out_degree, Rng& rng);

// Root-mean-square distance of x from the model's affine subspace (mean plus
// the span of its components), relative to |x - mean|: 0 for a vector the
// model can make exactly, 1 for one it holds nothing of.
double unexplained_fraction(const ShShapeModel& model, const std::vector<double>& x);

}  // namespace grainlab
