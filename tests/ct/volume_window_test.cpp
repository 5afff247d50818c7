// --crop and --bin: the slice-by-slice reduction against a direct average on
// random voxels, the grid it gives, and the same window read from a slice
// folder, a raw file and an NRRD file.
#include "ct_fixture.h"

#include "ct/image_io.h"
#include "ct/volume_window.h"
#include "core/error.h"

#include <random>

namespace grainlab::ct {
namespace {

namespace fs = std::filesystem;

GreyVolume random_volume(const Size3& size, unsigned seed) {
  GreyVolume v;
  v.size = size;
  v.spacing = Vec3(10e-6, 12e-6, 14e-6);
  v.origin = Vec3(1e-3, -2e-3, 3e-3);
  v.direction = Eigen::AngleAxisd(0.3, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  v.allocate();
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> grey(0, 65535);
  for (float& x : v.values) x = static_cast<float>(grey(rng));  // whole numbers: uint16 files hold them exactly
  return v;
}

// The window by its definition: the mean of each b^3 block of the box.
std::vector<float> brute_force(const GreyVolume& v, const CropBox& box, int b, Size3& out) {
  for (int a = 0; a < 3; ++a) out[a] = (box.hi[a] - box.lo[a]) / b;
  std::vector<float> values;
  for (std::int64_t k = 0; k < out[2]; ++k)
    for (std::int64_t j = 0; j < out[1]; ++j)
      for (std::int64_t i = 0; i < out[0]; ++i) {
        double sum = 0;
        for (int dz = 0; dz < b; ++dz)
          for (int dy = 0; dy < b; ++dy)
            for (int dx = 0; dx < b; ++dx)
              sum += v.at(box.lo[0] + i * b + dx, box.lo[1] + j * b + dy, box.lo[2] + k * b + dz);
        values.push_back(static_cast<float>(sum / (b * b * b)));
      }
  return values;
}

TEST(CtWindow, CropAndBinAverageTheBlocksOfTheBox) {
  const GreyVolume v = random_volume({13, 11, 9}, 7);
  const std::size_t n = static_cast<std::size_t>(v.size[0] * v.size[1]);
  const SliceReader from_memory = [&](std::int64_t z, std::vector<float>& s) {
    std::copy_n(v.values.begin() + static_cast<std::ptrdiff_t>(z * n), n, s.begin());
  };
  const CropBox box{{2, 1, 3}, {13, 10, 8}};
  for (int b : {1, 2, 3}) {
    const VolumeWindow w{box, b};
    Size3 out{};
    const std::vector<float> expected = brute_force(v, box, b, out);
    if (out[2] < 2) continue;
    EXPECT_EQ(windowed_size(v.size, w, "test"), out) << "bin " << b;
    const std::vector<float> got = read_windowed(v.size, w, from_memory);
    ASSERT_EQ(got.size(), expected.size());
    for (std::size_t i = 0; i < got.size(); ++i) EXPECT_NEAR(got[i], expected[i], 1e-3) << "bin " << b << " voxel " << i;

    // The output's voxel (0, 0, 0) sits at the centre of its block.
    GreyVolume grid = v;
    apply_window_grid(grid, w, "test");
    const Vec3 block_centre = v.world(Vec3(box.lo[0], box.lo[1], box.lo[2]) + Vec3::Constant((b - 1) / 2.0));
    EXPECT_LT((grid.world(Vec3::Zero()) - block_centre).norm(), 1e-15);
    const Vec3 next = v.world(Vec3(box.lo[0] + b, box.lo[1], box.lo[2]) + Vec3::Constant((b - 1) / 2.0));
    EXPECT_LT((grid.world(Vec3(1, 0, 0)) - next).norm(), 1e-15);
  }
}

TEST(CtWindow, EverySourceReadsTheSameWindow) {
  GreyVolume v = random_volume({12, 10, 8}, 3);
  v.direction.setIdentity();  // slices and raw files hold no direction
  v.origin.setZero();
  const fs::path dir = testing::fresh_folder("window_sources");
  write_grey_volume(v, dir / "v.nrrd", VoxelType::UInt16);
  write_grey_volume(v, dir / "v.raw", VoxelType::UInt16);
  write_grey_slices(v, dir / "slices", "z", ".png", VoxelType::UInt16);
  const VolumeWindow w{CropBox{{1, 2, 1}, {11, 10, 7}}, 2};
  const double voxel = v.spacing.x();
  const GreyVolume a = read_grey_volume({dir / "v.nrrd", std::nullopt, voxel, w});
  const GreyVolume b = read_grey_volume({dir / "v.raw", RawLayout{v.size, VoxelType::UInt16}, voxel, w});
  const GreyVolume c = read_grey_volume({dir / "slices", std::nullopt, voxel, w});
  EXPECT_EQ(a.size, (Size3{5, 4, 3}));
  EXPECT_EQ(a.values, b.values);
  EXPECT_EQ(a.values, c.values);
  EXPECT_EQ(a.spacing, Vec3::Constant(2 * voxel));
  EXPECT_LT((a.origin - Vec3(1.5, 2.5, 1.5) * voxel).norm(), 1e-18);
  fs::remove_all(dir);
}

TEST(CtWindow, ABoxOutsideTheImageIsRefused) {
  const Size3 full{10, 10, 10};
  EXPECT_THROW(windowed_size(full, VolumeWindow{CropBox{{0, 0, 0}, {11, 10, 10}}, 1}, "scan"), InputError);
  EXPECT_THROW(windowed_size(full, VolumeWindow{CropBox{{5, 0, 0}, {5, 10, 10}}, 1}, "scan"), InputError);
  EXPECT_THROW(windowed_size(full, VolumeWindow{CropBox{{0, 0, 0}, {3, 10, 10}}, 2}, "scan"), InputError);
  EXPECT_THROW(parse_crop({1, 2, 3}), InputError);
}

}  // namespace
}  // namespace grainlab::ct
