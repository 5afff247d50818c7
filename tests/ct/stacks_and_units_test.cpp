// A folder of 2D slices and an NRRD file in metres ("space units") read as
// the same scan as the NRRD file in millimetres, and segment to the same
// grains; the slice order is numeric, not alphabetical.
#include "ct_fixture.h"

#include "core/error.h"
#include "ct/image_io.h"
#include "ct/nrrd_header.h"
#include "ct/slice_stack.h"

#include <fmt/format.h>

namespace grainlab::ct {
namespace {

namespace fs = std::filesystem;
using testing::as_uint16;
using testing::expect_same_grains;

TEST(CtUnits, LengthUnitsAreKnownByTheirUsualNames) {
  EXPECT_EQ(metres_per_unit("m"), 1.0);
  EXPECT_EQ(metres_per_unit("meters"), 1.0);
  EXPECT_EQ(metres_per_unit("mm"), 1e-3);
  EXPECT_EQ(metres_per_unit("MM"), 1e-3);
  for (const char* micro : {"um", "\xc2\xb5m", "\xce\xbcm", "micron", "microns", "micrometre"}) {
    EXPECT_EQ(metres_per_unit(micro), 1e-6) << micro;
  }
  EXPECT_EQ(metres_per_unit(""), 0.0);     // no unit: the caller's default
  EXPECT_EQ(metres_per_unit("???"), 0.0);
  EXPECT_EQ(metres_per_unit("inch"), -1.0);
}

TEST(CtUnits, NrrdInMetresAndSliceFoldersSegmentLikeTheNrrdInMillimetres) {
  const SyntheticScene& scene = testing::small_scene();
  const GreyVolume reference = as_uint16(scene.volume);
  const double voxel = scene.volume.spacing.x();
  const fs::path dir = testing::fresh_folder("stacks_units");
  Progress quiet(false);

  write_grey_volume(scene.volume, dir / "mm.nrrd", VoxelType::UInt16);
  const ImageSource mm{dir / "mm.nrrd", std::nullopt, std::nullopt, {}};
  const Segmentation expected = segment_grey(read_grey_volume(mm), SegmentOptions{}, quiet);
  ASSERT_EQ(expected.grains.size(), scene.grains.size());

  // The same scan with its header in metres: 2.5e-05 "m" is 25 um, not 0.025 um.
  testing::write_nrrd_by_hand(dir / "m.nrrd", scene.volume, scene.volume.size, voxel,
                              "space units: \"m\" \"m\" \"m\"\n");
  const ImageSource m{dir / "m.nrrd", std::nullopt, std::nullopt, {}};
  const ImageHeader hm = read_image_header(m);
  EXPECT_NEAR(hm.spacing.x() / voxel, 1.0, 1e-12);
  EXPECT_NE(hm.spacing_source.find("space units"), std::string::npos) << hm.spacing_source;
  const GreyVolume from_m = read_grey_volume(m);
  ASSERT_EQ(from_m.values, reference.values);
  expect_same_grains(expected, segment_grey(from_m, SegmentOptions{}, quiet), "NRRD in m");

  // Slice folders: 16-bit TIFF and PNG, and float TIFF (the unrounded scan).
  write_grey_slices(scene.volume, dir / "tif16", "slice_", ".tif", VoxelType::UInt16);
  write_grey_slices(scene.volume, dir / "png16", "slice_", ".png", VoxelType::UInt16);
  write_grey_slices(scene.volume, dir / "tif32", "rec", ".tiff", VoxelType::Float32);
  for (const char* folder : {"tif16", "png16"}) {
    const ImageSource s{dir / folder, std::nullopt, voxel, {}};
    const ImageHeader h = read_image_header(s);
    EXPECT_EQ(h.size, reference.size) << folder;
    const GreyVolume v = read_grey_volume(s);
    ASSERT_EQ(v.values, reference.values) << folder;
    expect_same_grains(expected, segment_grey(v, SegmentOptions{}, quiet), folder);
  }
  const GreyVolume f = read_grey_volume({dir / "tif32", std::nullopt, voxel, {}});
  EXPECT_EQ(f.values, scene.volume.values) << "float slices";
  EXPECT_EQ(scan_slice_folder(dir / "tif32").pixel_type, "float32");
  fs::remove_all(dir);
}

// A detached header (.nhdr) with per-axis "spacings" in "units" of um: 25 um voxels.
TEST(CtUnits, DetachedNrrdWithSpacingsInMicrometres) {
  const SyntheticScene& scene = testing::small_scene();
  const fs::path dir = testing::fresh_folder("nhdr_units");
  write_grey_volume(scene.volume, dir / "scan.raw", VoxelType::UInt16);
  std::ofstream(dir / "scan.nhdr") << "NRRD0004\ntype: unsigned short\ndimension: 3\nsizes: 56 56 56\n"
                                      "spacings: 25 25 25\nunits: \"um\" \"um\" \"um\"\nendian: little\n"
                                      "encoding: raw\ndata file: scan.raw\n";
  const ImageHeader h = read_image_header({dir / "scan.nhdr", std::nullopt, std::nullopt, {}});
  EXPECT_NEAR(h.spacing.x() / 25e-6, 1.0, 1e-12);
  EXPECT_NE(h.spacing_source.find("'spacings' in the file's 'units"), std::string::npos) << h.spacing_source;
  EXPECT_EQ(read_grey_volume({dir / "scan.nhdr", std::nullopt, std::nullopt, {}}).values,
            as_uint16(scene.volume).values);
  // A spacing of exactly 1 is ITK's placeholder only when no unit is named: "1" in "mm" is read as 1 mm voxels.
  std::ofstream(dir / "one.nhdr") << "NRRD0004\ntype: unsigned short\ndimension: 3\nsizes: 56 56 56\n"
                                     "spacings: 1 1 1\nunits: \"mm\" \"mm\" \"mm\"\nendian: little\n"
                                     "encoding: raw\ndata file: scan.raw\n";
  EXPECT_NEAR(read_image_header({dir / "one.nhdr", std::nullopt, std::nullopt, {}}).spacing.x(), 1e-3, 1e-15);
  // The same header naming 40 slices of the data's 56: refused, naming the data file.
  std::ofstream(dir / "short.nhdr") << "NRRD0004\ntype: unsigned short\ndimension: 3\nsizes: 56 56 40\n"
                                       "spacings: 25 25 25\nunits: \"um\" \"um\" \"um\"\nendian: little\n"
                                       "encoding: raw\ndata file: scan.raw\n";
  try {
    read_image_header({dir / "short.nhdr", std::nullopt, std::nullopt, {}});
    ADD_FAILURE() << "a header describing less than its data file was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("holds more data than its header describes"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("scan.raw"), std::string::npos) << e.what();
  }
  fs::remove_all(dir);
}

TEST(CtStacks, SlicesAreOrderedByTheNumberInTheirNames) {
  EXPECT_EQ(parse_slice_name("scan_0012.tif").number, 12);
  EXPECT_EQ(parse_slice_name("scan_0012.tif").before, "scan_");
  EXPECT_EQ(parse_slice_name("r2_rec00000101.png").number, 101);  // the last number counts
  EXPECT_EQ(parse_slice_name("preview.tif").number, -1);
  EXPECT_EQ(parse_slice_name("scan_0012_v2.tif", 1).number, 12);
  EXPECT_EQ(parse_slice_name("scan_0012_v2.tif", 1).after, "_v2.tif");
  EXPECT_EQ(parse_slice_name("scan_0012_v2.tif", 2).number, -1);

  GreyVolume v;
  v.size = {5, 4, 12};
  v.spacing = Vec3::Constant(10e-6);
  v.allocate();
  for (std::size_t i = 0; i < v.values.size(); ++i) v.values[i] = static_cast<float>(i);
  const fs::path dir = testing::fresh_folder("natural_order");
  write_grey_slices(v, dir, "s", ".tif", VoxelType::UInt16);
  // Unpadded names: alphabetically s10 < s11 < s2, numerically s2 < s10.
  for (int z = 0; z < 12; ++z) fs::rename(dir / fmt::format("s{:04d}.tif", z), dir / fmt::format("s{}.tif", z + 1));
  std::ofstream(dir / "scan.log") << "reconstruction log: not a slice";
  const SliceStack stack = scan_slice_folder(dir);
  EXPECT_EQ(stack.first_number, 1);
  EXPECT_EQ(stack.files[9].filename().string(), "s10.tif");
  const GreyVolume back = read_grey_volume({dir, std::nullopt, 10e-6, {}});
  EXPECT_EQ(back.values, v.values);
  // A number shared by every name after the slice number (a version) is not the slice number.
  for (int z = 0; z < 12; ++z) {
    fs::rename(dir / fmt::format("s{}.tif", z + 1), dir / fmt::format("s{}_v2.tif", z + 1));
  }
  EXPECT_EQ(scan_slice_folder(dir).files[9].filename().string(), "s10_v2.tif");
  EXPECT_EQ(read_grey_volume({dir, std::nullopt, 10e-6, {}}).values, v.values);
  fs::remove_all(dir);
}

TEST(CtStacks, SynthWritesASliceFolderThatSegments) {
  const fs::path dir = testing::fresh_folder("synth_slices");
  const std::string slices = (dir / "slices").string() + "/";
  testing::Outcome o = testing::run_grainlab(
      "ct synth --size 40 --grains 2 --touching 0 --grain-size 12 --out " + slices, dir);
  ASSERT_EQ(o.code, 0) << o.err;
  EXPECT_NE(o.err.find("segment with --voxel-size 2.5e-05"), std::string::npos) << o.err;
  EXPECT_TRUE(fs::exists(dir / "slices" / "slice_0039.tif"));
  o = testing::run_grainlab("ct segment " + slices + " --voxel-size 25e-6 --out " + (dir / "out").string(), dir);
  ASSERT_EQ(o.code, 0) << o.err;
  std::ifstream csv(dir / "out" / "grains.csv");
  int lines = 0;
  for (std::string line; std::getline(csv, line);) ++lines;
  EXPECT_EQ(lines, 3) << "header and the two grains";
  EXPECT_TRUE(fs::exists(dir / "out" / "grain_quality.csv"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace grainlab::ct
