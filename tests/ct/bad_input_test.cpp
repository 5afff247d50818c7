// Bad images and bad output folders are refused by `grainlab ct segment` with
// a message that says what is wrong and how to fix it, and nothing is written.
#include "ct_fixture.h"

#include "ct/image_io.h"
#include "ct/segmentation_files.h"

#include <fmt/format.h>

#include <cstdlib>
#include <fstream>

namespace grainlab::ct {
namespace {

namespace fs = std::filesystem;
using testing::Outcome;
using testing::run_grainlab;

void write_bytes(const fs::path& p, std::size_t n) {
  std::ofstream out(p, std::ios::binary);
  const std::string zeros(n, '\0');
  out.write(zeros.data(), static_cast<std::streamsize>(n));
}

class CtBadInput : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = testing::fresh_folder(::testing::UnitTest::GetInstance()->current_test_info()->name()); }
  void TearDown() override { fs::remove_all(dir_); }

  // Expects a refusal (exit code 2) naming `message`, and no output folder.
  void expect_refused(const std::string& args, const std::string& message) {
    const Outcome o = run_grainlab("ct segment " + args + " --out " + (dir_ / "out").string(), dir_);
    EXPECT_EQ(o.code, 2) << o.err;
    EXPECT_NE(o.err.find(message), std::string::npos) << "stderr was: " << o.err;
    EXPECT_FALSE(fs::exists(dir_ / "out")) << "a refused run wrote its output folder";
    for (const auto& e : fs::directory_iterator(dir_)) {
      EXPECT_EQ(e.path().filename().string().find(".out.partial"), std::string::npos) << "staging folder left";
    }
  }

  fs::path dir_;
};

TEST_F(CtBadInput, RawFileOfTheWrongSize) {
  write_bytes(dir_ / "scan.raw", 10 * 10 * 10 * 2 + 100);
  expect_refused((dir_ / "scan.raw").string() + " --size 10 10 10 --type uint16 --voxel-size 25e-6",
                 "has 2100 bytes, more than the 2000 bytes of 10 x 10 x 10 voxels of uint16");
}

TEST_F(CtBadInput, TruncatedRawFile) {
  write_bytes(dir_ / "scan.raw", 1500);
  expect_refused((dir_ / "scan.raw").string() + " --size 10 10 10 --type uint16 --voxel-size 25e-6",
                 "is truncated: 1500 bytes, but --size and --type say 10 x 10 x 10 voxels of uint16, which need 2000");
}

TEST_F(CtBadInput, RawFileWithoutItsLayout) {
  write_bytes(dir_ / "scan.raw", 2000);
  expect_refused((dir_ / "scan.raw").string(), "give its layout with --size NX NY NZ and --type");
}

TEST_F(CtBadInput, EmptyFile) {
  write_bytes(dir_ / "scan.nrrd", 0);
  expect_refused((dir_ / "scan.nrrd").string(), "is empty (0 bytes)");
}

TEST_F(CtBadInput, ConstantGreyLevel) {
  GreyVolume v;
  v.size = {12, 12, 12};
  v.spacing = Vec3::Constant(25e-6);
  v.allocate(1234.0f);
  write_grey_volume(v, dir_ / "flat.nrrd", VoxelType::UInt16);
  expect_refused((dir_ / "flat.nrrd").string(), "the image is all one grey level (1234): there is nothing to segment");
}

TEST_F(CtBadInput, TwoDimensionalImage) {
  GreyVolume v;
  v.size = {12, 12, 1};
  v.spacing = Vec3::Constant(25e-6);
  v.allocate(0.0f);
  v.values[5] = 100;
  write_grey_volume(v, dir_ / "slice.tif", VoxelType::UInt16);
  write_grey_volume(v, dir_ / "slice.nrrd", VoxelType::UInt16);
  expect_refused((dir_ / "slice.tif").string() + " --voxel-size 25e-6", "is not a 3D image");
  expect_refused((dir_ / "slice.nrrd").string(), "is not a 3D image");
}

TEST_F(CtBadInput, TiffWithoutVoxelSize) {
  GreyVolume v;
  v.size = {8, 8, 8};
  v.allocate(0.0f);
  v.values[100] = 1;
  write_grey_volume(v, dir_ / "scan.tif", VoxelType::UInt8);
  expect_refused((dir_ / "scan.tif").string(), "does not give a voxel size (TIFF resolution tags are print densities");
}

TEST_F(CtBadInput, VolumeTooLargeForMemory) {
  // Compressed data: its length says nothing, so only the memory check can refuse it from the header.
  std::ofstream(dir_ / "huge.mha") << "ObjectType = Image\nNDims = 3\nDimSize = 6000 6000 6000\nElementType = "
                                      "MET_USHORT\nCompressedData = True\nCompressedDataSize = 1\n"
                                      "ElementSpacing = 0.025 0.025 0.025\nElementDataFile = LOCAL\n";
  expect_refused((dir_ / "huge.mha").string(), "is too large for this machine's memory: 6000 x 6000 x 6000 voxels need");
}

TEST_F(CtBadInput, NonEmptyOutputFolderNeedsForce) {
  const SyntheticScene& scene = testing::small_scene();
  write_grey_volume(scene.volume, dir_ / "scan.nrrd", VoxelType::UInt16);
  fs::create_directories(dir_ / "out");
  std::ofstream(dir_ / "out" / "notes.txt") << "mine";
  const std::string args = "ct segment " + (dir_ / "scan.nrrd").string() + " --quiet --out " + (dir_ / "out").string();
  Outcome o = run_grainlab(args, dir_);
  EXPECT_EQ(o.code, 2);
  EXPECT_NE(o.err.find("is not empty: choose a new folder, empty it, or give --force"), std::string::npos) << o.err;
  EXPECT_FALSE(fs::exists(dir_ / "out" / "grains.csv"));

  o = run_grainlab(args + " --force", dir_);
  ASSERT_EQ(o.code, 0) << o.err;
  EXPECT_TRUE(fs::exists(dir_ / "out" / "notes.txt")) << "--force replaces only grainlab's own files";
  std::ifstream csv(dir_ / "out" / "grains.csv");
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header, kGrainsCsvHeader);
  int rows = 0;
  for (std::string line; std::getline(csv, line);) {
    ++rows;
    EXPECT_TRUE(fs::exists(dir_ / "out" / mesh_file_name(rows, "stl"))) << line;
  }
  EXPECT_EQ(rows, static_cast<int>(scene.grains.size()));
  for (const auto& e : fs::directory_iterator(dir_)) {
    EXPECT_EQ(e.path().filename().string().find(".partial"), std::string::npos) << "staging folder left behind";
  }
}

// A small grey volume: 12 x 10 x `nz` voxels with a bright block.
GreyVolume block_volume(std::int64_t nx, std::int64_t nz) {
  GreyVolume v;
  v.size = {nx, 10, nz};
  v.spacing = Vec3::Constant(25e-6);
  v.allocate(100.0f);
  for (std::int64_t k = 1; k < nz - 1; ++k)
    for (std::int64_t j = 2; j < 8; ++j)
      for (std::int64_t i = 2; i < 8; ++i) v.at(i, j, k) = 200.0f;
  return v;
}

TEST_F(CtBadInput, SliceFolderWithAGap) {
  write_grey_slices(block_volume(12, 6), dir_ / "stack", "slice_", ".tif", VoxelType::UInt16);
  fs::remove(dir_ / "stack" / "slice_0003.tif");
  expect_refused((dir_ / "stack").string() + " --voxel-size 25e-6",
                 "has a gap in its numbering: 1 slice(s) missing between 'slice_0002.tif' and 'slice_0004.tif'");
}

// Writes a stack of 12 x 10 x 6 uint16 slices into dir/stack, then replaces
// slice `z` by the same slice of `other` written as `type`.
void stack_with_one_odd_slice(const fs::path& dir, const std::string& ext, const GreyVolume& other, VoxelType type,
                              int z) {
  write_grey_slices(block_volume(12, 6), dir / "stack", "slice_", ext, VoxelType::UInt16);
  write_grey_slices(other, dir / "other", "slice_", ext, type);
  const std::string name = fmt::format("slice_{:04d}{}", z, ext);
  fs::rename(dir / "other" / name, dir / "stack" / name);
}

TEST_F(CtBadInput, SliceFolderOfMixedSizes) {
  stack_with_one_odd_slice(dir_, ".tif", block_volume(11, 6), VoxelType::UInt16, 4);
  expect_refused((dir_ / "stack").string() + " --voxel-size 25e-6",
                 "slices of different sizes in '" + (dir_ / "stack").string() +
                     "': 'slice_0000.tif' is 12 x 10 pixels, but 'slice_0004.tif' is 11 x 10");
}

TEST_F(CtBadInput, SliceFolderOfMixedPixelTypes) {
  stack_with_one_odd_slice(dir_, ".png", block_volume(12, 6), VoxelType::UInt8, 2);
  expect_refused((dir_ / "stack").string() + " --voxel-size 25e-6",
                 "'slice_0000.png' holds uint16, but 'slice_0002.png' holds uint8");
}

// A TIFF header alone: one uint16 strip of w x h pixels, no pixel data (the
// headers are all that is read before the memory check).
// A TIFF of w x h 16-bit pixels whose pixels are a hole (a sparse file: no disk space taken).
void write_tiff_header(const fs::path& path, std::uint32_t w, std::uint32_t h) {
  std::string bytes = std::string("II*\0", 4) + std::string("\x08\0\0\0", 4);
  auto put16 = [&](std::uint16_t v) { bytes.append(reinterpret_cast<const char*>(&v), 2); };
  auto put32 = [&](std::uint32_t v) { bytes.append(reinterpret_cast<const char*>(&v), 4); };
  const std::uint32_t tags[][2] = {{256, w}, {257, h}, {258, 16}, {259, 1}, {262, 1}, {273, 134},
                                   {277, 1}, {278, h}, {279, w * h * 2}, {284, 1}};
  put16(10);
  for (const auto& t : tags) {
    put16(static_cast<std::uint16_t>(t[0]));
    put16(4);  // LONG
    put32(1);
    put32(t[1]);
  }
  put32(0);
  std::ofstream(path, std::ios::binary) << bytes;  // 134 bytes: the pixels start there
  fs::resize_file(path, bytes.size() + std::uint64_t{w} * h * 2);
}

TEST_F(CtBadInput, SliceFolderTooLargeForMemory) {
  fs::create_directories(dir_ / "stack");
  for (int z = 0; z < 100; ++z) write_tiff_header(dir_ / "stack" / fmt::format("s_{:04d}.tif", z), 40000, 40000);
  expect_refused((dir_ / "stack").string() + " --voxel-size 25e-6",
                 "is too large for this machine's memory: 40000 x 40000 x 100 voxels need about 5960.5 GiB");
}

TEST_F(CtBadInput, SliceFolderWithoutVoxelSize) {
  write_grey_slices(block_volume(12, 6), dir_ / "stack", "slice_", ".tif", VoxelType::UInt8);
  expect_refused((dir_ / "stack").string(), "does not give a voxel size (2D slices carry no slice spacing)");
}

TEST_F(CtBadInput, NrrdWrittenInMetresWithoutItsUnit) {
  // 2.5e-05 with no 'space units' reads as 2.5e-05 mm = 0.025 um.
  testing::write_nrrd_by_hand(dir_ / "scan.nrrd", block_volume(12, 6), {12, 10, 6}, 25e-6, "");
  expect_refused((dir_ / "scan.nrrd").string(),
                 "gives voxels of 0.025 um (0.025 x 0.025 x 0.025 um, from its header field 'space directions' read "
                 "as mm (the file has no 'space units'))");
  const Outcome o = run_grainlab("ct segment " + (dir_ / "scan.nrrd").string() + " --out " + (dir_ / "out").string(),
                                 dir_);
  EXPECT_NE(o.err.find("--voxel-size 25e-6"), std::string::npos) << o.err;
}

TEST_F(CtBadInput, ImplausibleVoxelSizeFlag) {
  write_grey_volume(block_volume(12, 6), dir_ / "scan.nrrd", VoxelType::UInt16);
  expect_refused((dir_ / "scan.nrrd").string() + " --voxel-size 25",
                 "--voxel-size 25 m (2.5e+07 um) is outside the voxel sizes of sand scans (0.1 to 1000 um)");
}

TEST_F(CtBadInput, NrrdUnitThatIsNotALength) {
  testing::write_nrrd_by_hand(dir_ / "scan.nrrd", block_volume(12, 6), {12, 10, 6}, 25,
                              "space units: \"furlong\" \"furlong\" \"furlong\"\n");
  expect_refused((dir_ / "scan.nrrd").string(), "NRRD 'space units' \"furlong\" is not a length unit grainlab knows");
}

TEST_F(CtBadInput, NrrdHeaderSmallerThanItsData) {
  // The header says 6 slices, the data holds 12: ITK would read half the scan as if it were all of it.
  testing::write_nrrd_by_hand(dir_ / "scan.nrrd", block_volume(12, 12), {12, 10, 6}, 0.025, "");
  expect_refused((dir_ / "scan.nrrd").string(),
                 "holds more data than its header describes: 'sizes: 12 10 6' of 'type: unsigned short' (1440 "
                 "bytes), but 2880 bytes of raw data after its header");
  testing::write_nrrd_by_hand(dir_ / "short.nrrd", block_volume(12, 6), {12, 10, 12}, 0.025, "");
  expect_refused((dir_ / "short.nrrd").string(), "is truncated or its header is wrong");
}

TEST_F(CtBadInput, MetaImageHeaderSmallerThanItsData) {
  // DimSize says 6 slices of uint16, the data (attached, then detached) holds 12.
  const std::string header = "ObjectType = Image\nNDims = 3\nDimSize = 12 10 6\nElementType = MET_USHORT\n"
                             "ElementSpacing = 0.025 0.025 0.025\nElementDataFile = ";
  const std::string data(12 * 10 * 12 * 2, '\x01');
  std::ofstream(dir_ / "scan.mha", std::ios::binary) << header << "LOCAL\n" << data;
  expect_refused((dir_ / "scan.mha").string(),
                 "(MetaImage) holds more data than its header describes: 'DimSize = 12 10 6' of 'ElementType = "
                 "MET_USHORT' (1440 bytes), but 2880 bytes of raw data after its header");
  std::ofstream(dir_ / "scan.mhd") << header << "scan_data.raw\n";
  std::ofstream(dir_ / "scan_data.raw", std::ios::binary) << data;
  expect_refused((dir_ / "scan.mhd").string(), "but 2880 bytes of raw data in '");
  std::ofstream(dir_ / "scan_data.raw", std::ios::binary) << data.substr(0, 1000);
  expect_refused((dir_ / "scan.mhd").string(), "is truncated or its header is wrong");
}

TEST_F(CtBadInput, ItkErrorsSayWhy) {
  write_grey_volume(block_volume(12, 6), dir_ / "scan.nrrd", VoxelType::UInt16);
  std::ifstream in(dir_ / "scan.nrrd", std::ios::binary);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  text.replace(text.find("type: unsigned short"), 20, "type: unsigned blah");
  std::ofstream(dir_ / "bad.nrrd", std::ios::binary) << text;
  expect_refused((dir_ / "bad.nrrd").string(), "couldn't parse type \"unsigned blah\"");
}

TEST_F(CtBadInput, CropOutsideTheImage) {
  write_grey_volume(block_volume(12, 6), dir_ / "scan.nrrd", VoxelType::UInt16);
  expect_refused((dir_ / "scan.nrrd").string() + " --crop 0,0,0,12,10,7",
                 "is not inside '" + (dir_ / "scan.nrrd").string() + "' (12 x 10 x 6 voxels)");
}

TEST_F(CtBadInput, HelpTeachesTheSteps) {
  const fs::path out = dir_ / "help.txt";
  const int status = std::system((std::string(GRAINLAB_BINARY) + " ct segment --help > " + out.string()).c_str());
  EXPECT_EQ(WEXITSTATUS(status), 0);
  const std::string help = grainlab::test::file_text(out);
  for (const char* word : {"Otsu", "h-maxima", "watershed", "--voxel-size", "metres", "Example:", "grains.csv",
                           "space units", "folder of 2D", "--crop", "--bin"}) {
    EXPECT_NE(help.find(word), std::string::npos) << word;
  }
}

}  // namespace
}  // namespace grainlab::ct
