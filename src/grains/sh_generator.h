// Random spherical-harmonic (SH) grains drawn from a sand's spectrum, after
// Garboczi (2002), Zhou and Wang (2017) and Wei et al. (2018): each grain
// gets, degree by degree, an amplitude A_n / A_0 drawn around the set's mean
// and spread, carried by random coefficients a_nm (a random direction among
// the 2n + 1 real degrees of freedom of degree n), so a real r. Method and
// its derivation at the top of sh_generator.cpp.
#pragma once

#include "core/rng.h"
#include "geometry/spherical_harmonics.h"
#include "grains/sh_shape_model.h"
#include "geometry/trimesh.h"

#include <cstdint>
#include <string>
#include <vector>

namespace grainlab {

// A sand's spectrum, as `grainlab grains spectrum` measures it: per degree
// n = 0..degree the mean and standard deviation over its grains of A_n / A_0
// (A_n = sqrt(sum_m |a_nm|^2); mean[0] = 1), and its grains' volume-equivalent
// diameters (m).
struct ShSpectrum {
  std::vector<double> mean;
  std::vector<double> std;
  double d_eq_mean = 0, d_eq_std = 0, d_eq_min = 0, d_eq_max = 0;  // m
  // The set's shape model (sh_shape_model.h), degree <= degree(); empty when
  // the spectrum has none.
  ShShapeModel model;

  int degree() const { return static_cast<int>(mean.size()) - 1; }
};

// Throws InputError naming the bad value: mean and std of different lengths
// or empty, mean[0] not 1, an amplitude or spread negative or not finite,
// d_eq not 0 < min <= mean <= max with std >= 0, a bad model or one of a
// degree above the spectrum's.
void validate(const ShSpectrum& spectrum);

// How generate_sh_grains draws a grain's coefficients.
//  - random_phase: every degree n >= 1 from the spectrum alone (amplitude
//    and a random direction), degrees independent (Garboczi 2002).
//  - shape_model: the degrees <= K of the spectrum's model (draw_from_model:
//    mean plus principal components with random scores, the residual with
//    random phases), the degrees above K as random_phase draws them.
enum class ShMethod { random_phase, shape_model };

// "random-phase" / "shape-model"; parse throws InputError listing the names.
const char* sh_method_name(ShMethod method);
ShMethod parse_sh_method(const std::string& name);

// Sets the coefficients of degree n (1 <= n <= c.degree) to a random
// direction among its 2n + 1 real degrees of freedom (uniform under
// rotations), of amplitude sqrt(sum_m |a_nm|^2) = `amplitude`, with
// a_{n,-m} = (-1)^m conj(a_nm).
void set_random_degree(ShCoefficients& c, int n, double amplitude, Rng& rng);

// One random draw of coefficients of the spectrum's degree, with a_00 =
// sqrt(4 pi) (mean radius about 1): A_n / A_0 drawn from the lognormal of
// the spectrum's mean and std for n (exactly the mean where std = 0). Its r
// may be <= 0 somewhere: generate_sh_grains rejects such draws.
// With ShMethod::shape_model the degrees <= K come from the model instead.
ShCoefficients draw_sh_coefficients(const ShSpectrum& spectrum, Rng& rng,
                                    ShMethod method = ShMethod::random_phase);

// The d_eq of one grain (m): lognormal of the spectrum's mean and std,
// clamped to [d_eq_min, d_eq_max].
double draw_equivalent_diameter(const ShSpectrum& spectrum, Rng& rng);

// Most draws tried for one grain before the spectrum is refused as too rough
// for star-shaped grains.
inline constexpr int kMaxShDraws = 200;

struct ShGrains {
  std::vector<ShCoefficients> coefficients;  // per grain, in metres, about the SH origin (before the move below)
  std::vector<TriMesh> meshes;               // per grain: `faces` triangles, metres, centred, principal frame
  int rejected = 0;                          // draws refused for r <= 0 somewhere, all grains together
};

// `count` grains: per grain its own generator (seeded from `seed`), draws of
// draw_sh_coefficients until r > 0 everywhere (sh_mesh's check), scaled to a
// draw_equivalent_diameter, meshed at `faces` triangles (sh_mesh), moved to
// its centroid and rotated into its principal frame. The same arguments give
// the same grains bit for bit, whatever the thread count. Throws InputError
// for a bad spectrum, count < 1, faces < 8, or a spectrum whose draws keep
// reaching r <= 0 (kMaxShDraws times for one grain), or shape_model asked
// of a spectrum without a model.
ShGrains generate_sh_grains(const ShSpectrum& spectrum, int count, std::uint64_t seed, int faces,
                            ShMethod method = ShMethod::random_phase);

}  // namespace grainlab
