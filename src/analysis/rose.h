// What the report draws of a set of contact normals (paper Fig. 15), sampled
// here so that the report (grainlab.report) only plots.
//
// Rose histogram. Each normal is counted as n and -n (normals have no sign),
// binned by n_z (uniform in [-1, 1]) and the azimuth atan2(n_y, n_x) (uniform
// in [-pi, pi]): since dOmega = dn_z dazimuth, every bin has the same solid
// angle omega = 4 pi / (n_z n_az). The density of a bin is count / (2 N omega)
// in 1/sr, so the densities integrate to 1 over the sphere (sum density omega
// = 1), like Kanatani's f. Bins: about 25 normals per bin on average,
// n_z = clamp(round(sqrt(2N / 50)), 5, 18) and n_az = 2 n_z.
//
// Kanatani grid. f(n) of kanatani.h at theta_i = pi i / (n_theta - 1) (polar,
// from +z) and phi_j = -pi + 2 pi j / (n_phi - 1) (azimuth from +x), both
// ends included (a closed surface for plotting), n = (sin theta cos phi,
// sin theta sin phi, cos theta).
#pragma once

#include "analysis/kanatani.h"
#include "core/types.h"

#include <span>
#include <vector>

namespace grainlab::analysis {

struct RoseHistogram {
  std::vector<double> z_edges;        // n_z + 1 edges in n_z, from -1 to 1
  std::vector<double> azimuth_edges;  // n_az + 1 edges in rad, from -pi to pi
  std::vector<double> density;        // n_z x n_az, row-major by n_z bin (1/sr)
};

// The histogram of unit `normals` (rules above); empty vectors for no normals.
RoseHistogram rose_histogram(std::span<const Vec3> normals);

struct DensityGrid {
  std::vector<double> theta;    // polar angles (rad)
  std::vector<double> phi;      // azimuths (rad)
  std::vector<double> density;  // theta.size() x phi.size(), row-major by theta (1/sr)
};

// Kanatani's f sampled on the (theta, phi) grid above.
DensityGrid sample_density(const KanataniDensity& f, int n_theta = 31, int n_phi = 61);

}  // namespace grainlab::analysis
