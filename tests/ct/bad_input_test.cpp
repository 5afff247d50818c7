// Bad images and bad output folders are refused by `grainlab ct segment` with
// a message that says what is wrong and how to fix it, and nothing is written.
#include "ct_fixture.h"

#include "ct/image_io.h"
#include "ct/segmentation_files.h"

#include <cstdlib>
#include <fstream>
#include <sstream>

namespace grainlab::ct {
namespace {

namespace fs = std::filesystem;

struct Outcome {
  int code = 0;
  std::string err;
};

// Runs the grainlab binary with `args`, returning its exit code and standard error.
Outcome run_grainlab(const std::string& args, const fs::path& dir) {
  const fs::path err = dir / "stderr.txt";
  const std::string cmd = std::string(GRAINLAB_BINARY) + " " + args + " > /dev/null 2> " + err.string();
  const int status = std::system(cmd.c_str());
  std::ifstream in(err);
  std::stringstream s;
  s << in.rdbuf();
  return {WEXITSTATUS(status), s.str()};
}

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
  std::ofstream(dir_ / "huge.mha") << "ObjectType = Image\nNDims = 3\nDimSize = 6000 6000 6000\nElementType = "
                                      "MET_USHORT\nElementSpacing = 0.025 0.025 0.025\nElementDataFile = LOCAL\n";
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

TEST_F(CtBadInput, HelpTeachesTheSteps) {
  const fs::path out = dir_ / "help.txt";
  const int status = std::system((std::string(GRAINLAB_BINARY) + " ct segment --help > " + out.string()).c_str());
  EXPECT_EQ(WEXITSTATUS(status), 0);
  std::ifstream in(out);
  std::stringstream s;
  s << in.rdbuf();
  for (const char* word : {"Otsu", "h-maxima", "watershed", "--voxel-size", "metres", "Example:", "grains.csv"}) {
    EXPECT_NE(s.str().find(word), std::string::npos) << word;
  }
}

}  // namespace
}  // namespace grainlab::ct
