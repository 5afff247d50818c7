// Every image format round-trips the synthetic scan, and segmenting each copy
// gives the same grains.
#include "ct_fixture.h"

#include "ct/image_io.h"
#include "ct/raw_volume.h"

#include <cmath>

namespace grainlab::ct {
namespace {

namespace fs = std::filesystem;
using testing::as_uint16;
using testing::expect_same_grains;

TEST(CtFormats, EachFormatRoundTripsAndSegmentsTheSame) {
  const SyntheticScene& scene = testing::small_scene();
  const GreyVolume reference = as_uint16(scene.volume);
  const fs::path dir = testing::fresh_folder("formats");
  Progress quiet(false);
  const Segmentation expected = segment_grey(reference, SegmentOptions{}, quiet);
  ASSERT_EQ(expected.grains.size(), scene.grains.size());

  const double voxel = scene.volume.spacing.x();
  const RawLayout layout{reference.size, VoxelType::UInt16};
  struct Case {
    std::string file;
    ImageSource source;
  };
  const std::vector<Case> cases = {
      {"scan.tif", {dir / "scan.tif", std::nullopt, voxel, {}}},  // TIFF holds no voxel size
      {"scan.nrrd", {dir / "scan.nrrd", std::nullopt, std::nullopt, {}}},
      {"scan.mha", {dir / "scan.mha", std::nullopt, std::nullopt, {}}},
      {"scan.raw", {dir / "scan.raw", layout, voxel, {}}},
  };
  for (const Case& c : cases) {
    write_grey_volume(scene.volume, c.source.path, VoxelType::UInt16);
    const ImageHeader h = read_image_header(c.source);
    EXPECT_EQ(h.size, reference.size) << c.file;
    EXPECT_NEAR(h.spacing.x() / voxel, 1.0, 1e-12) << c.file;
    const GreyVolume back = read_grey_volume(c.source);
    ASSERT_EQ(back.values, reference.values) << c.file << ": voxels changed on the way";
    expect_same_grains(expected, segment_grey(back, SegmentOptions{}, quiet), c.file);
  }
  // Nothing but the four files (no temporary left behind).
  int files = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++files;
  EXPECT_EQ(files, 4);
  fs::remove_all(dir);
}

TEST(CtFormats, LabelImagesRoundTrip) {
  LabelVolume labels;
  labels.size = {7, 5, 4};
  labels.spacing = Vec3(1e-5, 2e-5, 3e-5);
  labels.origin = Vec3(1e-3, -2e-3, 0.5e-3);
  labels.allocate(0);
  for (std::size_t i = 0; i < labels.values.size(); ++i) labels.values[i] = static_cast<std::uint32_t>(i % 5);
  const fs::path dir = testing::fresh_folder("labels");
  for (const char* name : {"labels.nrrd", "labels.mha"}) {
    write_label_volume(labels, dir / name);
    const LabelVolume back = read_label_volume({dir / name, std::nullopt, std::nullopt, {}});
    EXPECT_EQ(back.values, labels.values) << name;
    EXPECT_LT((back.spacing - labels.spacing).norm(), 1e-15) << name;
    EXPECT_LT((back.origin - labels.origin).norm(), 1e-15) << name;
  }
  fs::remove_all(dir);
}

TEST(CtFormats, VoxelSizeOptionWinsOverTheFile) {
  const fs::path dir = testing::fresh_folder("spacing");
  GreyVolume v;
  v.size = {4, 4, 4};
  v.spacing = Vec3::Constant(10e-6);
  v.allocate(1.0f);
  write_grey_volume(v, dir / "v.nrrd", VoxelType::Float32);
  EXPECT_NEAR(read_image_header({dir / "v.nrrd", std::nullopt, std::nullopt, {}}).spacing.x(), 10e-6, 1e-18);
  const ImageHeader h = read_image_header({dir / "v.nrrd", std::nullopt, 7e-6, {}});
  EXPECT_EQ(h.spacing, Vec3::Constant(7e-6));
  EXPECT_EQ(h.spacing_source, "--voxel-size");
  fs::remove_all(dir);
}

}  // namespace
}  // namespace grainlab::ct
