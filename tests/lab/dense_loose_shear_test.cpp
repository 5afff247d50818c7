// A dense specimen behaves densely, a loose one loosely (issue 10 item 4), on
// a small box of frictional spheres (cheap: analytic spheres, 345 of
// them), both sheared at 100 kPa to 10 % strain at I = 1e-3, each kind as
// the mean of three specimens (seeds):
//   dense (frictionless deposition, compaction): the stress ratio peaks before
//     6 % strain, has fallen by at least 5 % of the peak at 10 %, and the
//     specimen dilates;
//   loose (deposition with the test's friction): it contracts before it
//     dilates, and peaks lower and later (does not soften: see the test).
// Dr is on the spheres' own index void ratios in this box (below), not on a
// real sand's: the box walls loosen a packing only a few grains across, so
// these spheres' e_min is far above a sand's.
//
// The stress ratio of ~350 grains jumps by up to 0.1 between samples as force
// chains form and buckle, so peak and value at 10 % are read from the curve
// smoothed by a running mean over 11 samples (+-0.5 % strain), truncated at
// the ends, of the mean curve.
#include "lab/direct_shear.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <iterator>
#include <vector>

using namespace grainlab;

namespace {

// Own index void ratios of these spheres in this box (the same grain count):
// e_min = frictionless deposition + compaction under 100 kPa, e_max =
// deposition with friction 0.5 + compaction under 100 kPa, measured with
// `grainlab run` on the spec below (deposition_friction 0 and 0.5). With
// friction 1.0 the spheres did not settle until session 5 (their spin did
// not decay: the critical step ignored the damping, dynamics/time_step.h);
// they do now, but this looser end is not re-measured here. A pile
// measured without compaction (cap lowered onto it) gives e = 1.13 for the
// frictionless and 1.08 for the frictional deposition: its rough top, not its
// density, sets that number, so e_max is taken after compaction. Both were
// measured with the box's gap open during preparation (until session 18);
// with it closed the walls are flat at mid-height and the frictionless
// specimens of seeds 3-5 come out denser, e = 0.741-0.749 (0.751-0.759 open; Dr 1.13-1.25 on
// these indices), the frictional ones at 0.849-0.873.
constexpr double kEMin = 0.761;
constexpr double kEMax = 0.840;

// Six specimens of each kind. One specimen of 345 spheres is too noisy to
// judge alone (measured, session 18, with the gap closed during preparation,
// seeds 3-7): dense peaks at 2.7-4.3 % save seed 3's, whose ratio fell from
// 0.77 at 2 % to 0.63 at 7 % and jammed back up to 0.82 at 9 %; of five
// loose specimens, three were still at their lowest at 10 %. Three were not
// enough either: their means moved with any change of the engine's rounding
// (below).
constexpr std::uint64_t kSeeds[] = {3, 4, 5, 6, 7, 8};

LabSpec sphere_spec(double deposition_friction) {
  LabSpec spec;
  spec.grains.preset = "glass-beads";
  spec.grains.shapes = 4;
  spec.material.grain.friction = 0.5;  // more than glass (0.12): a clear peak and dilation in a small box
  // About 8 diameters across and 5 high: in a 5 mm box (199 spheres) the
  // friction-0.5 deposition (e = 0.874 against 0.785 dense) dilated from the
  // start, and in a 4.2 mm box (120) the dense curve rose again to 0.75 at
  // 10 % (grains wedged at the gap): too few grains to tell dense from loose.
  spec.box.length = spec.box.width = 6.0e-3;
  spec.box.height = 4.1e-3;
  spec.specimen.void_ratio = 0.75;  // sets the grain count (345 spheres)
  spec.specimen.tolerance = 1;      // the test checks Dr itself
  spec.specimen.deposition_friction = deposition_friction;
  spec.settings<ShearSpec>().final_strain = 0.10;
  spec.numerics.inertial_number = 1e-3;
  spec.numerics.threads = 2;
  spec.output.strain_interval = 0.001;
  return spec;
}

struct Curve {
  double e = 0, dr = 0;
  std::vector<double> strain, ratio, dv;  // dv: cap displacement, up = dilation (m)
};

Curve shear(double deposition_friction, std::uint64_t seed) {
  LabSpec spec = sphere_spec(deposition_friction);
  spec.seed = seed;
  DirectShearTest t(spec);
  while (t.advance(5000)) {
  }
  Curve c;
  c.e = t.achieved_void_ratio();
  c.dr = (kEMax - c.e) / (kEMax - kEMin);
  const auto& cols = shear_series_columns();
  const auto col = [&](const char* name) { return std::find(cols.begin(), cols.end(), name) - cols.begin(); };
  for (const auto& row : t.series()) {
    c.strain.push_back(row[col("shear_strain")]);
    c.ratio.push_back(row[col("stress_ratio")]);
    c.dv.push_back(row[col("vertical_displacement_m")]);
  }
  return c;
}

// The mean response of specimens prepared alike with other seeds: their
// curves averaged sample by sample (every run samples the same strains),
// the stress ratio then smoothed; peak and value at 10 % read from it.
struct Mean {
  std::vector<double> strain, ratio, dv;
  double dr_min = 1e9, dr_max = -1e9;
  double peak = 0, peak_strain = 0, at_end = 0;
  double rise = 0;  // the largest rise of the cap above a low point it reached before (m)
};

Mean mean_of(double deposition_friction) {
  Mean m;
  for (std::uint64_t seed : kSeeds) {
    const Curve c = shear(deposition_friction, seed);
    m.dr_min = std::min(m.dr_min, c.dr), m.dr_max = std::max(m.dr_max, c.dr);
    if (m.strain.empty()) {
      m.strain = c.strain;
      m.ratio.assign(c.strain.size(), 0.0);
      m.dv.assign(c.strain.size(), 0.0);
    }
    const std::size_t n = std::min(m.strain.size(), c.strain.size());
    m.strain.resize(n), m.ratio.resize(n), m.dv.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      EXPECT_NEAR(c.strain[i], m.strain[i], 1e-3) << "the runs sample other strains";
      m.ratio[i] += c.ratio[i] / std::size(kSeeds);
      m.dv[i] += c.dv[i] / std::size(kSeeds);
    }
  }
  const int n = static_cast<int>(m.ratio.size()), h = 5;
  std::vector<double> smooth(n);
  for (int i = 0; i < n; ++i) {
    const int a = std::max(0, i - h), b = std::min(n - 1, i + h);
    for (int j = a; j <= b; ++j) smooth[i] += m.ratio[j] / (b - a + 1);
  }
  const int k = static_cast<int>(std::max_element(smooth.begin(), smooth.end()) - smooth.begin());
  m.peak = smooth[k], m.peak_strain = m.strain[k], m.at_end = smooth.back();
  double low = 0;
  for (double v : m.dv) low = std::min(low, v), m.rise = std::max(m.rise, v - low);
  const auto lowest = std::min_element(m.dv.begin(), m.dv.end()) - m.dv.begin();
  std::printf("friction %.1f: Dr %.2f to %.2f, mean curve peak %.3f at %.1f %%, %.3f at 10 %%; cap %.1f um at 1 %%, "
              "lowest %.1f um at %.1f %%, %.1f um at 10 %%, largest rise from a low %.1f um\n",
              deposition_friction, m.dr_min, m.dr_max, m.peak, 100 * m.peak_strain, m.at_end, 1e6 * m.dv[n / 10],
              1e6 * m.dv[lowest], 100 * m.strain[lowest], 1e6 * m.dv.back(), 1e6 * m.rise);
  return m;
}

}  // namespace

// One test: the comparison needs both means (twelve runs, about 45 s on one
// core).
// Measured with one specimen (seed 3, session 6): dense e = 0.759 (Dr 1.02),
// smoothed peak 0.831 at 3.9 %, 0.508 at 10 % (39 % below the peak), cap up
// 150 um; loose e = 0.847 (Dr -0.09), cap down to -47 um at 7 %, -21 um at
// 10 %, smoothed maximum 0.570 at 3.9 % on a plateau (0.46-0.57 from 3.5 %
// on), 0.545 at 10 % (4.4 % below its maximum). The means are printed.
// Means of three read with the rounding of the sphere-sphere geometry
// changed by an ulp (three ways, seeds 3-5, 6-8, 9-11; 2026-12-07) broke
// every claim this test made in one variant or another: the dense mean's
// peak ranged 0.66-0.87, its drop to 10 % 0.1-37 %, the loose cap's rise
// from a low 3-26 um, the loose mean's drop 0-17 %. Means of six, the
// same variants (seeds 3-8 and 6-11): dense peak 0.65-0.83 at 2.0-5.9 %,
// 13-34 % lower at 10 %, cap up 144-161 um; loose cap 9-15 um down at 1 %,
// peak 0.54-0.59 at 7.8-10 %, cap 16-41 um down at 10 %; every claim below
// held in each. Two claims were dropped, as no count of specimens this
// test can afford decides them: that the loose cap rises 5 um from a low
// point after contracting, and that the loose mean softens by less than
// half the dense one's drop (a loose chain collapsing near 10 % drops it).
TEST(DenseLooseShear, DenseSpecimenPeaksEarlySoftensAndDilatesLooseContractsAndPeaksLowerLater) {
  const Mean d = mean_of(0.0);
  EXPECT_GE(d.dr_min, 0.9);
  EXPECT_LT(d.peak_strain, 0.06);
  EXPECT_LE(d.at_end, 0.95 * d.peak);
  EXPECT_GT(d.dv.back(), 0.0);

  const Mean c = mean_of(0.5);
  EXPECT_LE(c.dr_max, 0.3);
  // Contracts first: the cap goes down (still below its start at 1 % strain),
  // and ends far below the dense one (less than half its rise).
  EXPECT_LT(c.dv[c.dv.size() / 10], 0.0);
  EXPECT_LT(c.dv.back(), 0.5 * d.dv.back());
  // Peaks lower and later: a lower maximum of the mean curve, reached at a
  // larger strain.
  EXPECT_LT(c.peak, d.peak);
  EXPECT_GT(c.peak_strain, d.peak_strain);
}
