// An NRRD or MetaImage header is read with its lines bounded, and an encoded
// NRRD (gzip, ascii, hex) whose data is too short to hold the image its header
// claims is refused from the header, before ITK allocates that image: a small
// file cannot make grainlab take gigabytes.
#include "ct_fixture.h"

#include "core/error.h"
#include "ct/image_io.h"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

namespace grainlab::ct {
namespace {

namespace fs = std::filesystem;

class CtHeaderBounds : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = testing::fresh_folder(::testing::UnitTest::GetInstance()->current_test_info()->name()); }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path write(const std::string& name, const std::string& bytes) {
    const fs::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << bytes;
    return p;
  }
  // The message of the InputError that reading the header of `path` throws ("" if none).
  static std::string refusal(const fs::path& path) {
    ImageSource source;
    source.path = path;
    try {
      read_image_header(source);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }

  fs::path dir_;
};

std::string nrrd_header(const std::string& sizes, const std::string& type, const std::string& encoding) {
  return "NRRD0004\ntype: " + type + "\ndimension: 3\nsizes: " + sizes + "\nspacings: 0.02 0.02 0.02\nencoding: " +
         encoding + "\n\n";
}

// 64 values "0 1 2 ... 63": 4^3 voxels in ASCII.
std::string ascii_values() {
  std::string s;
  for (int i = 0; i < 64; ++i) s += std::to_string(i) + " ";
  return s;
}

TEST_F(CtHeaderBounds, AGzipNrrdClaimingMoreThanItsDataCanHoldIsRefused) {
  // 1000^3 voxels of 2 bytes (2 GB) need at least 2e9 / 1032 bytes of gzip data; the file has 100.
  const fs::path p = write("claims.nrrd", nrrd_header("1000 1000 1000", "unsigned short", "gzip") + std::string(100, 'x'));
  const std::string msg = refusal(p);
  EXPECT_NE(msg.find("cannot hold the image its header describes"), std::string::npos) << msg;
  EXPECT_NE(msg.find("(2000000000 bytes) need at least 1937984 bytes"), std::string::npos) << msg;
  EXPECT_NE(msg.find("gzip packs at most 1032 bytes into one"), std::string::npos) << msg;
  EXPECT_NE(msg.find("holds 100 after its header"), std::string::npos) << msg;
}

TEST_F(CtHeaderBounds, AnAsciiNrrdIsReadWhenItsValuesFitAndRefusedWhenTheHeaderClaimsMore) {
  EXPECT_EQ(refusal(write("fits.nrrd", nrrd_header("4 4 4", "float", "ascii") + ascii_values())), "");
  // 5^3 = 125 values need at least 249 characters; the 64 values take 182.
  const std::string msg = refusal(write("claims.nrrd", nrrd_header("5 5 5", "float", "ascii") + ascii_values()));
  EXPECT_NE(msg.find("need at least 249 bytes of encoded data (each value takes a digit and a separator)"),
            std::string::npos)
      << msg;
}

TEST_F(CtHeaderBounds, AHeaderLineOverItsBoundIsRefusedBeforeItIsReadWhole) {
  const std::string long_line(70000, 'a');  // no newline: a raw scan named .nrrd would look like this
  for (const char* name : {"noise.nrrd", "noise.mha"}) {
    const std::string text = std::string(name) == "noise.nrrd" ? "NRRD0004\n" + long_line : long_line;
    const std::string msg = refusal(write(name, text));
    EXPECT_NE(msg.find("a line of more than 65536 characters"), std::string::npos) << name << ": " << msg;
  }
  const std::string msg = refusal(write("magic.nrrd", long_line));
  EXPECT_NE(msg.find("a line of more than 65536 characters where an NRRD header has short text lines"),
            std::string::npos)
      << msg;
}

// A header line that is no field, comment or key/value pair made ITK's NRRD
// reader overflow a buffer and abort the process (found by fuzzing).
TEST_F(CtHeaderBounds, AnNrrdHeaderLineOfNoFieldIsRefused) {
  const std::string msg = refusal(write("line.nrrd", "NRRD0004\ntype unsigned char\ndimension: 3\n\n"));
  EXPECT_NE(msg.find("NRRD header line 2 ('type unsigned char') is neither a field ('name: value')"),
            std::string::npos)
      << msg;
}

// A 'space directions' vector of a malformed number thousands of characters
// long made teem overflow its message buffer on its stack (found by fuzzing:
// tests/fuzz/corpus/nrrd/crash_space_directions_b75dbb86).
TEST_F(CtHeaderBounds, AMalformedSpaceVectorIsRefusedBeforeTeemParsesIt) {
  const std::string head = "NRRD0004\ntype: unsigned char\ndimension: 3\nspace: left-posterior-superior\nsizes: 2 2 2\n";
  const std::string data = "encoding: raw\n\n" + std::string(8, '\x01');
  const fs::path bad = write("bad.nrrd", head + "space directions: (0.025,0,0) (0,0.025*5:62,0) (0,0,0.025)\n" + data);
  EXPECT_NE(refusal(bad).find("'0.025*5:62' is not a number"), std::string::npos) << refusal(bad);
  const fs::path open = write("open.nrrd", head + "space directions: (0.025,0,0) (0,0.025,0 (0,0,0.025)\n" + data);
  EXPECT_NE(refusal(open).find("'0 (0' is not a number"), std::string::npos) << refusal(open);
  const fs::path hidden = write("hidden.nrrd", head + "space directions: (0.025,0,0) (0,0.0 :=2,0) (0,0,0.025)\n" + data);
  EXPECT_NE(refusal(hidden).find("'0.0 :=2' is not a number"), std::string::npos)
      << "':=' after 'name: ' is a field, as teem reads it: " << refusal(hidden);
  const fs::path long_field = write("long.nrrd", head + "content: " + std::string(1000, 'c') + "\n" + data);
  EXPECT_NE(refusal(long_field).find("has 1009 characters, more than the 900 a field"), std::string::npos)
      << refusal(long_field);
  const fs::path good = write("good.nrrd", head + "space directions: (0.025,0,0) (0,0.025,0) (0,0,0.025)\nspace "
                                                  "units: \"mm\" \"mm\" \"mm\"\n" + data);
  EXPECT_EQ(refusal(good), "");
}

// ASCII data holding a run of over 1024 characters without a space
// overflowed teem's value buffer on its stack (found by fuzzing:
// tests/fuzz/corpus/nrrd/crash_ascii_value_038a0762), in the file or in a
// detached data file; values of ordinary length are read.
TEST_F(CtHeaderBounds, AnAsciiNrrdValueLongerThanTeemsBufferIsRefused) {
  const std::string head = nrrd_header("4 4 4", "float", "ascii");
  const std::string msg = refusal(write("run.nrrd", head + "0.0 0.5 " + std::string(1200, '3') + " " + ascii_values()));
  EXPECT_NE(msg.find("its data holds 1001 characters without a space at byte " + std::to_string(head.size() + 8)),
            std::string::npos)
      << msg;
  write("values.txt", "1 2 " + std::string(1500, '7'));
  const std::string detached = refusal(write("detached.nhdr", "NRRD0004\ntype: float\ndimension: 3\nsizes: 4 4 4\n"
                                                              "encoding: ascii\ndata file: values.txt\n\n"));
  EXPECT_NE(detached.find("values.txt' (NRRD, ascii encoding): its data holds 1001 characters without a space at "
                          "byte 4"),
            std::string::npos)
      << detached;
  EXPECT_EQ(refusal(write("fine.nrrd", head + std::string(1000, '1') + " " + ascii_values())), "");
}

}  // namespace
}  // namespace grainlab::ct
