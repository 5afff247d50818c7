// The quality table flags a phantom's merged pair and split grain, measures
// their contacts against the analytic cross-section, and flags nothing in a
// correctly segmented synthetic scan.
#include "ct_fixture.h"

#include "ct/grain_quality.h"

#include <cmath>
#include <numbers>

namespace grainlab::ct {
namespace {

constexpr double kVoxel = 25e-6;
constexpr double kRadius = 8;  // voxels

// Labels `label` on the voxels whose centre lies in the ball (and, for
// cut_x > 0, on the side x < cut_x; the rest of the ball gets label + 1).
void paint_ball(LabelVolume& v, const Vec3& c, std::uint32_t label, double cut_x = 0) {
  for (std::int64_t k = 0; k < v.size[2]; ++k)
    for (std::int64_t j = 0; j < v.size[1]; ++j)
      for (std::int64_t i = 0; i < v.size[0]; ++i) {
        if ((Vec3(i, j, k) - c).norm() > kRadius) continue;
        v.at(i, j, k) = cut_x > 0 && i >= cut_x ? label + 1 : label;
      }
}

TEST(CtGrainQuality, FlagsAMergedPairAndASplitGrainOfAPhantom) {
  LabelVolume v;
  v.size = {90, 30, 30};
  v.spacing = Vec3::Constant(kVoxel);
  v.allocate(0);
  // Label 1: two balls whose centres are 15 voxels apart (a neck of radius
  // sqrt(8^2 - 7.5^2) = 2.8 voxels) given one label, as a segmentation that
  // missed the neck would.
  paint_ball(v, Vec3(12, 15, 15), 1);
  paint_ball(v, Vec3(27, 15, 15), 1);
  paint_ball(v, Vec3(47, 15, 15), 2);       // a lone ball
  paint_ball(v, Vec3(75, 15, 15), 3, 75);   // one ball cut through its centre: labels 3 and 4
  Progress quiet(false);
  const Segmentation s = segment_labels(v, SegmentOptions{}, quiet);
  ASSERT_EQ(s.grains.size(), 4u);
  const GrainQuality& merged = s.grains[0].quality;
  const GrainQuality& lone = s.grains[1].quality;
  EXPECT_EQ(merged.distance_maxima, 2);
  EXPECT_LT(merged.convexity, kMergeConvexity);  // two balls over their hull: 0.8
  EXPECT_GT(merged.convexity, 0.75);
  EXPECT_TRUE(merged.likely_merge);
  EXPECT_FALSE(merged.likely_split);
  EXPECT_EQ(merged.contacts, 0);

  EXPECT_EQ(lone.distance_maxima, 1);
  EXPECT_GT(lone.convexity, 0.97);
  EXPECT_FALSE(lone.likely_merge);
  EXPECT_FALSE(lone.likely_split);
  EXPECT_EQ(lone.contacts, 0);

  // The halves share the ball's central disc, pi r^2 (the voxel faces count
  // it as the lattice points of the disc, within a few per cent).
  const double disc = std::numbers::pi * kRadius * kRadius * kVoxel * kVoxel;
  for (int g : {2, 3}) {
    const GrainQuality& half = s.grains[g].quality;
    EXPECT_EQ(half.contacts, 1);
    EXPECT_NEAR(half.contact_area / disc, 1.0, 0.05);
    // Over the cross-section of a half's equivalent ball, (1/2)^(2/3) of the whole one's: 1.59.
    EXPECT_NEAR(half.largest_contact_ratio, std::pow(2.0, 2.0 / 3.0), 0.1);
    EXPECT_TRUE(half.likely_split);
    EXPECT_FALSE(half.likely_merge);
  }
}

TEST(CtGrainQuality, ContactAreasCountTheFacesBetweenLabels) {
  LabelVolume v;
  v.size = {4, 3, 2};
  v.spacing = Vec3(1, 2, 3);
  v.allocate(0);
  for (std::int64_t k = 0; k < 2; ++k)
    for (std::int64_t j = 0; j < 3; ++j) {
      v.at(0, j, k) = 1;
      v.at(1, j, k) = 2;  // 6 faces normal to x between 1 and 2, each 2 x 3
      v.at(3, j, k) = 3;  // label 3 is apart from 2 (a pore column between)
    }
  v.at(2, 0, 0) = 3;  // touches 2 across one x face and 3 itself
  const std::vector<LabelContact> c = label_contacts(v);
  ASSERT_EQ(c.size(), 2u);
  EXPECT_EQ(c[0].a, 1u);
  EXPECT_EQ(c[0].b, 2u);
  EXPECT_DOUBLE_EQ(c[0].area, 6 * 6.0);
  EXPECT_EQ(c[1].a, 2u);
  EXPECT_EQ(c[1].b, 3u);
  EXPECT_DOUBLE_EQ(c[1].area, 6.0);
}

TEST(CtGrainQuality, ACorrectSegmentationIsNotFlagged) {
  Progress quiet(false);
  const Segmentation s = segment_grey(testing::small_scene().volume, SegmentOptions{}, quiet);
  ASSERT_EQ(s.grains.size(), testing::small_scene().grains.size());
  int touching = 0;
  for (const SegmentedGrain& g : s.grains) {
    EXPECT_EQ(g.quality.distance_maxima, 1) << "grain " << g.id;
    EXPECT_FALSE(g.quality.likely_merge) << "grain " << g.id << " convexity " << g.quality.convexity;
    EXPECT_FALSE(g.quality.likely_split) << "grain " << g.id << " ratio " << g.quality.largest_contact_ratio;
    touching += g.quality.contacts;
  }
  EXPECT_EQ(touching, 2) << "the scan's touching pair: one contact each";
}

}  // namespace
}  // namespace grainlab::ct
