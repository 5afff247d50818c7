// Fitting SH coefficients to a mesh (see sh_fit.h).
//
// The Y_nm are orthonormal, so the coefficients that minimise the integral of
// (r - sum a_nm Y_nm)^2 over the sphere are the projections a_nm = integral
// of r conj(Y_nm). The quadrature of band 2N integrates r conj(Y_nm) exactly
// for the degrees <= 2N of r, so degrees N+1..2N, which a mesh's r always
// has, do not alias into the fit; what is left above 2N is small for a grain
// of a few thousand faces. The residual r - r_fit is measured at the same
// directions: its weighted mean square is the RMS error over the sphere.
#include "grains/sh_fit.h"

#include "core/error.h"
#include "geometry/mass_properties.h"
#include "geometry/radial_profile.h"

#include <cmath>
#include <numbers>

namespace grainlab {

ShFit fit_sh(const TriMesh& mesh, int degree, const std::string& name) {
  if (degree < 0 || degree > 100) input_error("{}: the SH degree must be in 0..100, got {}", name, degree);
  const MassProperties mp = mass_properties(mesh);
  const SphereQuadrature q = sphere_quadrature(2 * degree);
  const std::vector<double> r = radial_profile(mesh, mp.centroid, q.directions, name);
  ShFit fit{sh_project(q, r, degree)};
  fit.centre = mp.centroid;
  fit.equivalent_diameter = std::cbrt(6 * mp.volume / std::numbers::pi);
  fit.directions = static_cast<int>(r.size());
  const std::vector<double> fitted = sh_radii(fit.coefficients, q);
  double sum = 0;
  for (std::size_t i = 0; i < r.size(); ++i) {
    const double e = r[i] - fitted[i];
    sum += q.weights[i] * e * e;
    fit.max_error = std::max(fit.max_error, std::abs(e));
  }
  fit.rms_error = std::sqrt(sum / (4 * std::numbers::pi));
  return fit;
}

}  // namespace grainlab
