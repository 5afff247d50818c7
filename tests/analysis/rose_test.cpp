// Rose histogram and Kanatani grid (analysis/rose.h, fabric_result.h): both
// integrate to one over the sphere and show the anisotropy they are built from.
#include "analysis/fabric_result.h"
#include "analysis/rose.h"
#include "core/rng.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

using namespace grainlab;
using namespace grainlab::analysis;

namespace {

constexpr double kPi = std::numbers::pi;

// Integral over the sphere of the sampled grid: trapezoid rule in theta
// (weight sin theta) and in phi (the phi = +-pi seam counted once).
double integrate(const DensityGrid& g) {
  const std::size_t nt = g.theta.size(), np = g.phi.size();
  const double dt = g.theta[1] - g.theta[0], dp = g.phi[1] - g.phi[0];
  double sum = 0;
  for (std::size_t i = 0; i < nt; ++i)
    for (std::size_t j = 0; j + 1 < np; ++j) {
      const double w = (i == 0 || i + 1 == nt) ? 0.5 : 1.0;
      sum += w * g.density[i * np + j] * std::sin(g.theta[i]) * dt * dp;
    }
  return sum;
}

std::vector<Vec3> stretched_normals(std::size_t count) {
  Rng rng(7);
  std::vector<Vec3> n(count);
  for (Vec3& v : n) v = Vec3(rng.normal(), 0.7 * rng.normal(), 2.0 * rng.normal()).normalized();
  return n;
}

}  // namespace

TEST(KanataniGrid, IntegratesToOneAndPeaksAlongTheStretch) {
  const FabricTensors f = fabric_tensors(stretched_normals(5000));
  const DensityGrid g = sample_density(kanatani_density(f));
  ASSERT_EQ(g.theta.size(), 31u);
  ASSERT_EQ(g.phi.size(), 61u);
  EXPECT_DOUBLE_EQ(g.theta.front(), 0.0);
  EXPECT_DOUBLE_EQ(g.theta.back(), kPi);
  EXPECT_DOUBLE_EQ(g.phi.front(), -kPi);
  // The trapezoid rule in theta is second order (h = pi/30): measured 3.7e-3 off.
  EXPECT_NEAR(integrate(g), 1.0, 5e-3);
  // Normals stretched along z: denser at the pole than at the equator.
  EXPECT_GT(g.density[0], g.density[15 * 61 + 30]);
  // Isotropic (D = 0): 1/(4 pi) everywhere.
  const DensityGrid iso = sample_density(KanataniDensity{});
  for (double d : iso.density) EXPECT_DOUBLE_EQ(d, 1 / (4 * kPi));
}

TEST(RoseHistogram, DensitiesIntegrateToOneAndCountBothSigns) {
  const std::vector<Vec3> n = stretched_normals(4000);
  const RoseHistogram h = rose_histogram(n);
  // 8000 counts / 25 per bin / 2: sqrt(160) -> 13 bands in n_z, 26 in azimuth.
  ASSERT_EQ(h.z_edges.size(), 14u);
  ASSERT_EQ(h.azimuth_edges.size(), 27u);
  ASSERT_EQ(h.density.size(), 13u * 26u);
  const double omega = 4 * kPi / (13 * 26);
  double total = 0;
  for (double d : h.density) total += d * omega;
  EXPECT_NEAR(total, 1.0, 1e-12);
  // n and -n both counted: the histogram is point-symmetric (bin (i, j) and
  // its antipode (n_z - 1 - i, j +- n_az / 2)).
  for (std::size_t i = 0; i < 13; ++i)
    for (std::size_t j = 0; j < 26; ++j) EXPECT_DOUBLE_EQ(h.density[i * 26 + j], h.density[(12 - i) * 26 + (j + 13) % 26]);
  // Stretched along z: the polar bands hold more than the equatorial one.
  EXPECT_GT(h.density[0], h.density[6 * 26]);
}

TEST(RoseHistogram, FewNormalsGiveTheSmallestGridAndNoneGiveNothing) {
  const std::vector<Vec3> one = {Vec3(0, 0, 2)};  // not unit: normalised
  const RoseHistogram h = rose_histogram(one);
  ASSERT_EQ(h.density.size(), 5u * 10u);
  // +z in the top band, -z in the bottom one: each half the normals over one bin's solid angle.
  const double omega = 4 * kPi / 50;
  double top = 0, bottom = 0;
  for (std::size_t j = 0; j < 10; ++j) top += h.density[4 * 10 + j], bottom += h.density[j];
  EXPECT_DOUBLE_EQ(top, 0.5 / omega);
  EXPECT_DOUBLE_EQ(bottom, 0.5 / omega);
  EXPECT_TRUE(rose_histogram({}).density.empty());
}

TEST(FabricResult, NoContactsLeaveAnEmptyResult) {
  State s;
  s.bodies.resize(3);
  const FabricResult r = fabric_result(s);
  EXPECT_EQ(r.contacts, 0u);
  EXPECT_TRUE(r.normals.empty());
  EXPECT_TRUE(r.kanatani_grid.density.empty());
}
