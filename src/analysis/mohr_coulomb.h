// The Mohr-Coulomb envelope tau = c' + sigma' tan(phi') fitted over the Mohr
// circles of several drained triaxial runs.
//
// A run at cell pressure sigma_3 and stress ratio eta = q/p' (at its peak or
// at its critical state) has, with p' = (sigma_1 + 2 sigma_3)/3 and
// q = sigma_1 - sigma_3, sigma_1 (3 - eta) = sigma_3 (3 + 2 eta):
//     sigma_1 = sigma_3 (3 + 2 eta) / (3 - eta),   0 <= eta < 3.
// Alone (c' = 0) its friction angle has sin phi' = 3 eta / (6 + eta).
//
// The fit. A circle of centre s' = (sigma_1 + sigma_3)/2 and radius
// t = (sigma_1 - sigma_3)/2 touches the line tau = c' + sigma' tan phi' when
// the distance from (s', 0) to it equals t:
//     (c' + s' tan phi') / sqrt(1 + tan^2 phi') = t,
// i.e. (multiplying by cos phi')  t = c' cos phi' + s' sin phi' = a + b s'.
// So the envelope tangent to every circle is the straight line t = a + b s'
// in the s'-t plane, with sin phi' = b and c' = a / cos phi'. Least squares
// of t on s' over the circles,
//     b = sum (s_i - s_mean)(t_i - t_mean) / sum (s_i - s_mean)^2,
//     a = t_mean - b s_mean,
// is the exact common tangent when the (s', t) points line up (two circles
// always do) and the best straight envelope otherwise: R^2 = 1 - SS_res/SS_tot
// and the rms residual sqrt(SS_res / n) of t tell how far they are from a line.
#pragma once

#include <span>

namespace grainlab::analysis {

// sigma_1 of a triaxial compression at cell pressure sigma3 and stress ratio
// eta = q/p' (any stress unit); InputError unless sigma3 > 0 and 0 <= eta < 3.
double triaxial_sigma1(double sigma3, double eta);

// One Mohr circle in the s'-t plane: s = (sigma_1 + sigma_3)/2, t = (sigma_1 - sigma_3)/2.
struct MohrCircle {
  double s = 0, t = 0;
};

MohrCircle mohr_circle(double sigma1, double sigma3);

struct MohrCoulombFit {
  double phi_deg = 0;          // phi'
  double c = 0;                // c', in the circles' stress unit
  double a = 0;                // c' cos phi', the intercept of t = a + b s'
  double sin_phi = 0;          // b
  double r_squared = 0;        // of t on s' (1 when every t is equal)
  double rms_residual = 0;     // of t, in the stress unit
  int circles = 0;
};

// The least-squares envelope of the circles (above). InputError, saying why,
// when there are fewer than two circles, when every circle has the same
// centre, or when the best line's slope sin phi' is outside (0, 1).
MohrCoulombFit fit_mohr_coulomb(std::span<const MohrCircle> circles);

}  // namespace grainlab::analysis
