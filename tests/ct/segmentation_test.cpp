// The segmentation of the synthetic scan against the grains it was made from.
#include "ct_fixture.h"

#include "core/timer.h"
#include "geometry/shape_metrics.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <set>

namespace grainlab::ct {
namespace {

using testing::match_grains;
using testing::standard_scene;

// Roundness tolerance per kind at 36 voxels across. Sub-angular grains come
// out rounder by up to 0.07 here and 0.01-0.13 over six scans, the concave
// ones by -0.07 to +0.06 (docs/ct.md, "Known limits"): shallow corners' radii
// move by up to a hundred times a sub-voxel apex error, and a dent's rim is a
// few voxels across here. That is a limit of the resolution (at 72 voxels the
// concave grains are within 0.05: the next test), stated here rather than
// hidden in a global tolerance.
double roundness_tolerance(const std::string& kind) {
  return kind == "sub-angular" || kind == "concave" ? 0.08 : 0.05;
}

// Segments `scene`, checks every grain against its source and prints the figures.
void check_scene(const SyntheticScene& scene, bool verbose, bool assert_roundness,
                 double (*tolerance)(const std::string&) = roundness_tolerance, SegmentOptions options = {}) {
  std::map<std::string, std::pair<double, double>> by_kind;  // kind -> (sum of |error|, max |error|)
  std::map<std::string, int> count;
  Progress quiet(false);
  const Segmentation seg = segment_grey(scene.volume, options, quiet);
  ASSERT_EQ(seg.grains.size(), scene.grains.size()) << "a grain was merged, split or lost";
  const std::vector<int> match = match_grains(scene, seg);
  EXPECT_EQ(std::set<int>(match.begin(), match.end()).size(), match.size()) << "two true grains matched one";

  const double voxel = scene.volume.spacing.x();
  double worst_v = 0, worst_c = 0, worst_r = 0;
  for (std::size_t g = 0; g < scene.grains.size(); ++g) {
    const SyntheticGrain& t = scene.grains[g];
    const SegmentedGrain& s = seg.grains[match[g]];
    const MassProperties truth = mass_properties(t.mesh);
    const double dv = s.volume / truth.volume - 1;
    const double dc = (s.centroid - truth.centroid).norm() / voxel;
    const double r_true = shape_metrics(t.mesh).roundness, r_seg = shape_metrics(s.mesh).roundness;
    if (verbose) std::printf("  grain %zu %-11s volume %+5.2f %%  centroid %.3f voxel  roundness %.3f -> %.3f (%+.3f)\n", g + 1,
                t.kind.c_str(), 100 * dv, dc, r_true, r_seg, r_seg - r_true);
    EXPECT_LT(std::abs(dv), 0.03) << "grain " << g + 1 << " (" << t.kind << ")";
    EXPECT_LT(dc, 1.0) << "grain " << g + 1 << " (" << t.kind << ")";
    if (assert_roundness) {
      EXPECT_LT(std::abs(r_seg - r_true), tolerance(t.kind)) << "grain " << g + 1 << " (" << t.kind << ")";
    }
    by_kind[t.kind].first += std::abs(r_seg - r_true);
    by_kind[t.kind].second = std::max(by_kind[t.kind].second, std::abs(r_seg - r_true));
    ++count[t.kind];
    EXPECT_FALSE(s.border);
    EXPECT_LE(static_cast<int>(s.mesh.faces.size()), s.within_budget ? 2000 : 1 << 20);
    worst_v = std::max(worst_v, std::abs(dv));
    worst_c = std::max(worst_c, dc);
    worst_r = std::max(worst_r, std::abs(r_seg - r_true));
  }
  std::printf("  worst: volume %.2f %%, centroid %.3f voxel, roundness %.3f; threshold %.0f\n", 100 * worst_v, worst_c,
              worst_r, seg.threshold);
  for (const auto& [kind, e] : by_kind) {
    std::printf("  %-11s x%2d: roundness error mean %.3f, max %.3f\n", kind.c_str(), count[kind], e.first / count[kind],
                e.second);
  }
}

TEST(CtSegmentation, FindsEveryGrainWithItsVolumeCentroidAndRoundness) {
  EXPECT_EQ(standard_scene().touching.size(), 2u);
  check_scene(standard_scene(), true, true);
}

// The standard scan's grains at twice the resolution (voxel 12.5 um, 72
// voxels across, 288^3; the default --h, scaled with the grains): the
// concave grains' roundness is within 0.05 (12 of 12 over six such scans,
// the worst 0.027; docs/ct.md), as are the ellipsoids and rounded grains.
// Sub-angular grains keep 0.08: 10 of 12 within 0.05 over those scans, the
// others +0.050 and +0.073, the roundness measure's sensitivity to shallow
// corners (docs/ct.md, Known limits). Seed 6: the scan on which the old
// ball-bite dents failed (concave +0.108 and +0.052; now +0.002 and +0.003),
// so this test tells the two apart; seed 1 did not (+0.048). About 30 s and
// 0.9 GB.
double roundness_tolerance_72_voxels(const std::string& kind) { return kind == "sub-angular" ? 0.08 : 0.05; }

TEST(CtSegmentation, AtSeventyTwoVoxelsAcrossConcaveRoundnessIsWithin005) {
  SyntheticSpec spec;
  spec.voxel_size = 12.5e-6;
  spec.size = 288;
  spec.grain_size = 72;
  spec.seed = 6;
  check_scene(make_synthetic_scene(spec), true, true, roundness_tolerance_72_voxels);
}

// The watershed's depth chosen from the grains' size (h = 0, the default), without the merge step:
// small grains (14 voxels across) that a fixed depth of 2 voxels merges into
// one (a touching pair's neck is within 2 voxels of the smaller grain's
// inscribed radius here) come out one by one: their median inscribed radius
// is about 4 voxels, a fifth of it less than the least depth, 1 voxel.
// (At 72 voxels across the default is about 5 voxels, the test above.)
TEST(CtSegmentation, TheDefaultDepthScalesWithTheGrainsAndSplitsSmallTouchingGrains) {
  SyntheticSpec spec;
  spec.voxel_size = 25e-6 * 36 / 14;
  spec.size = 100;
  spec.grain_size = 14;
  spec.seed = 2;
  const SyntheticScene scene = make_synthetic_scene(spec);
  Progress quiet(false);
  // h-maxima alone (the merge step off): the depth is what is tested here.
  SegmentOptions fixed;
  fixed.h = 2;
  fixed.merge_ratio = 0;
  EXPECT_LT(segment_grey(scene.volume, fixed, quiet).grains.size(), scene.grains.size())
      << "this scan no longer tells the depths apart";
  SegmentOptions depth_only;
  depth_only.merge_ratio = 0;
  const Segmentation seg = segment_grey(scene.volume, depth_only, quiet);
  EXPECT_NEAR(seg.typical_radius, 0.26 * spec.grain_size, 1.0);
  EXPECT_DOUBLE_EQ(seg.h, std::max(1.0, 0.2 * seg.typical_radius));
  ASSERT_EQ(seg.grains.size(), scene.grains.size()) << "a grain was merged, split or lost at h = " << seg.h;
  const std::vector<int> match = match_grains(scene, seg);
  EXPECT_EQ(std::set<int>(match.begin(), match.end()).size(), match.size()) << "two true grains matched one";
  EXPECT_EQ(segment_grey(scene.volume, SegmentOptions{}, quiet).grains.size(), scene.grains.size())
      << "the merge step (the default) merged, split or lost a grain";
}

// The larger scan of docs/ct.md (256^3, 60 grains of 30 voxels, 10 touching
// pairs): about 45 s, so run by hand:
//   build/test_ct --gtest_also_run_disabled_tests --gtest_filter='*LargeScan*'
TEST(CtSegmentation, DISABLED_LargeScan) {
  SyntheticSpec spec;
  spec.size = 256;
  spec.grains = 60;
  spec.touching_pairs = 10;
  spec.grain_size = 30;
  Stopwatch clock;
  const SyntheticScene scene = make_synthetic_scene(spec);
  std::printf("  scan made in %.1f s\n", clock.seconds());
  clock.reset();
  check_scene(scene, false, false);  // roundness: figures only (30-voxel grains, docs/ct.md)
  std::printf("  segmented and checked in %.1f s\n", clock.seconds());
}

// The orientation is the principal frame: its first axis is the grain's long axis.
TEST(CtSegmentation, OrientationIsThePrincipalFrame) {
  const SyntheticScene& scene = testing::small_scene();
  Progress quiet(false);
  const Segmentation seg = segment_grey(scene.volume, SegmentOptions{}, quiet);
  ASSERT_EQ(seg.grains.size(), scene.grains.size());
  for (const SegmentedGrain& g : seg.grains) {
    EXPECT_NEAR(g.orientation.norm(), 1.0, 1e-12);
    EXPECT_GE(g.orientation.w(), 0.0);
    const PrincipalFrame f = principal_frame(g.mesh);
    EXPECT_LT((g.orientation.toRotationMatrix() - f.axes).norm(), 1e-9);
  }
}

// A label image (the truth, rasterised) skips steps 1-3 and gives the same grains.
TEST(CtSegmentation, LabelImagesAreMeshedAsGiven) {
  const SyntheticScene& scene = testing::small_scene();
  Progress quiet(false);
  const Segmentation grey = segment_grey(scene.volume, SegmentOptions{}, quiet);
  LabelVolume labels;
  labels.copy_grid(scene.volume);
  labels.allocate(0);
  // Label each voxel by the grey segmentation's nearest grain centre, where the grey level is solid.
  for (std::int64_t k = 0; k < labels.size[2]; ++k) {
    for (std::int64_t j = 0; j < labels.size[1]; ++j) {
      for (std::int64_t i = 0; i < labels.size[0]; ++i) {
        if (scene.volume.at(i, j, k) <= grey.threshold) continue;
        const Vec3 p = labels.world(Vec3(i, j, k));
        std::uint32_t best = 0;
        double best_d = 1e300;
        for (const SegmentedGrain& g : grey.grains) {
          const double d = (g.centroid - p).norm();
          if (d < best_d) {
            best_d = d;
            best = static_cast<std::uint32_t>(g.id);
          }
        }
        labels.at(i, j, k) = best;
      }
    }
  }
  const Segmentation lab = segment_labels(labels, SegmentOptions{}, quiet);
  ASSERT_EQ(lab.grains.size(), grey.grains.size());
  for (std::size_t g = 0; g < lab.grains.size(); ++g) {
    EXPECT_NEAR(lab.grains[g].volume / grey.grains[g].volume, 1.0, 0.06);
    EXPECT_LT((lab.grains[g].centroid - grey.grains[g].centroid).norm(), scene.volume.spacing.x());
  }
}

}  // namespace
}  // namespace grainlab::ct
