// grainlab's own strict reading of a MetaImage header (ct/metaimage_header.h),
// before ITK's MetaIO: a header as ITK writes it passes; each field that
// breaks the rules (repeated, misspelt, not a field, a control character,
// numbers that disagree with NDims, a missing or absent data file) is refused
// naming its line.
#include "ct_fixture.h"

#include "core/error.h"
#include "ct/metaimage_header.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <fstream>
#include <string>

namespace grainlab::ct {
namespace {

namespace fs = std::filesystem;

const std::string kFields =
    "ObjectType = Image\nNDims = 3\nBinaryData = True\nBinaryDataByteOrderMSB = False\nCompressedData = False\n"
    "TransformMatrix = 1 0 0 0 1 0 0 0 1\nOffset = 0 0 0\nCenterOfRotation = 0 0 0\nAnatomicalOrientation = RAI\n"
    "ElementSpacing = 0.025 0.025 0.025\nDimSize = 4 3 2\nElementType = MET_UCHAR\n";

class MetaImageHeader : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = testing::fresh_folder(::testing::UnitTest::GetInstance()->current_test_info()->name()); }
  void TearDown() override { fs::remove_all(dir_); }

  // The InputError's message checking `fields`, `data_file` and `data` (24 voxels) throws ("" if none).
  std::string refusal(const std::string& fields, const std::string& data_file = "ElementDataFile = LOCAL\n",
                      const std::string& data = std::string(24, '\x07')) {
    const fs::path p = dir_ / "scan.mha";
    std::ofstream(p, std::ios::binary | std::ios::trunc) << fields << data_file << data;
    try {
      check_metaimage_header(p);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }

  fs::path dir_;
};

std::string replaced(std::string s, const std::string& from, const std::string& to) {
  return s.replace(s.find(from), from.size(), to);
}

TEST_F(MetaImageHeader, AHeaderAsItkWritesItPasses) {
  EXPECT_EQ(refusal(kFields), "");
  EXPECT_EQ(refusal(kFields + "ITK_InputFilterName = MetaImageIO\n"), "") << "a field of another name";
}

TEST_F(MetaImageHeader, EachBrokenFieldIsRefusedNamingItsLine) {
  EXPECT_NE(refusal("NDims = 3\n" + kFields).find("line 3): field 'NDims' given a second time (first on line 1)"),
            std::string::npos);
  EXPECT_NE(refusal(replaced(kFields, "NDims", "NGims")).find("line 2): 'NGims' is not a MetaImage field (a misspelt "
                                                              "'NDims'?)"),
            std::string::npos);
  EXPECT_NE(refusal("a line of no field\n" + kFields).find("line 1): 'a line of no field' is not a 'Key = Value'"),
            std::string::npos);
  EXPECT_NE(refusal(replaced(kFields, "RAI", "R\x01I")).find("holds the control character 0x01"), std::string::npos);
  EXPECT_NE(refusal(replaced(kFields, "DimSize = 4 3 2", "DimSize = 4 3")).find("holds 2 numbers, but NDims = 3"),
            std::string::npos);
  EXPECT_NE(refusal(replaced(kFields, "0.025 0.025 0.025", "0.025 -1 0.025")).find("'-1' is not a number > 0"),
            std::string::npos);
  EXPECT_NE(refusal(replaced(kFields, "MET_UCHAR", "MET_UCHAT")).find("is not a MetaImage element type"),
            std::string::npos);
  EXPECT_NE(refusal(replaced(kFields, "CompressedData = False", "CompressedData = Maybe")).find("neither True nor"),
            std::string::npos);
  EXPECT_NE(refusal("BinaryData" + std::string(300, 'V') + " = True\n" + kFields)
                .find("line 1): a field name of 310 characters ('BinaryDataVVVV"),
            std::string::npos)
      << "MetaIO copied a name into 255 bytes (tests/fuzz/corpus/metaimage/crash_long_field_name_3d3cf5df)";
  EXPECT_EQ(refusal("ITK_" + std::string(196, 'k') + " = a value\n" + kFields), "") << "200 characters";
  EXPECT_NE(refusal("Name = " + std::string(300, '\xff') + "\n" + kFields)
                .find("line 1): the value of 'Name' is a text of 300 characters, more than the 254"),
            std::string::npos)
      << "MetaIO copied text into 255 bytes (tests/fuzz/corpus/metaimage/crash_long_text_value_11bf7fd3)";
  EXPECT_EQ(refusal("Name = " + std::string(254, 'n') + "\n" + kFields), "");
  EXPECT_NE(refusal(kFields, "ElementDataFile = " + std::string(300, 'd') + ".raw\n")
                .find("give the data file's path relative to the header's folder"),
            std::string::npos)
      << "a long data file path (a deep absolute folder) is told how to fit";
  EXPECT_NE(refusal(kFields, "", "").find("no 'ElementDataFile' field"), std::string::npos);
  EXPECT_NE(refusal(kFields, "ElementDataFile = LOCALo\n").find("its data file '"), std::string::npos);
  EXPECT_NE(refusal(replaced(kFields, "DimSize = 4 3 2", "DimSize = 4 3 4")).find("is truncated or its header is "
                                                                                  "wrong"),
            std::string::npos)
      << "the data's length is still checked";
}

// ElementDataFile = LIST: the slice files' names follow, one a line. An
// empty line made MetaIO read through a wild pointer (found by fuzzing:
// tests/fuzz/corpus/metaimage/crash_empty_slice_name_5d53e8c7); a printf
// pattern is a format MetaIO hands to printf.
TEST_F(MetaImageHeader, SliceFilesAreListedOneALineOrByAPatternOfOneNumber) {
  for (const char* name : {"s0.raw", "s1.raw"}) std::ofstream(dir_ / name, std::ios::binary) << std::string(12, 'x');
  EXPECT_EQ(refusal(kFields, "ElementDataFile = LIST\n", "s0.raw\ns1.raw\n"), "");
  EXPECT_EQ(refusal(kFields, "ElementDataFile = LIST 2\n", "s0.raw\ns1.raw\n"), "");
  EXPECT_NE(refusal(kFields, "ElementDataFile = LIST\n", "s0.raw\n\n")
                .find("line 15): slice file 2 of the 2 that 'ElementDataFile = LIST' and DimSize call for is an empty "
                      "line"),
            std::string::npos);
  EXPECT_NE(refusal(kFields, "ElementDataFile = LIST\n", "s0.raw\n").find("slice file 2 of the 2 that "
                                                                           "'ElementDataFile = LIST' and DimSize call "
                                                                           "for is missing"),
            std::string::npos);
  EXPECT_NE(refusal(kFields, "ElementDataFile = LIST\n", "s0.raw\nnone.raw\n").find("none.raw' does not exist"),
            std::string::npos);
  EXPECT_NE(refusal(kFields, "ElementDataFile = LISTCALOL\n", "s0.raw\ns1.raw\n")
                .find("line 13): 'ElementDataFile = LISTCALOL' starts with LIST, which MetaIO reads as a list"),
            std::string::npos);
  EXPECT_EQ(refusal(kFields, "ElementDataFile = s%d.raw 0 1 1\n", ""), "");
  EXPECT_NE(refusal(kFields, "ElementDataFile = s%s.raw 0 1 1\n", "").find("is not a slice pattern"),
            std::string::npos);
  EXPECT_NE(refusal(kFields, "ElementDataFile = s%03d.raw 0\n", "").find("is not a slice pattern"), std::string::npos);
}

std::string zlib_of(const std::string& bytes) {
  uLongf size = compressBound(bytes.size());
  std::string out(size, '\0');
  compress2(reinterpret_cast<Bytef*>(out.data()), &size, reinterpret_cast<const Bytef*>(bytes.data()), bytes.size(), 6);
  out.resize(size);
  return out;
}

// MetaIO inflated compressed data until the image was full, for ever when the
// stream broke or ended first (found by fuzzing: a hang,
// tests/fuzz/corpus/metaimage/hang_broken_zlib_ee684a79): grainlab inflates it
// first.
TEST_F(MetaImageHeader, CompressedDataMustInflateToTheWholeImage) {
  const std::string fields = replaced(kFields, "CompressedData = False", "CompressedData = True");
  EXPECT_EQ(refusal(fields, "ElementDataFile = LOCAL\n", zlib_of(std::string(24, '\x07'))), "");
  EXPECT_NE(refusal(fields, "ElementDataFile = LOCAL\n", "not zlib data\n")
                .find("line 13): its compressed data is broken (zlib: incorrect header check) after 0 of the 24 bytes "
                      "that 'DimSize = 4 3 2' of 'ElementType = MET_UCHAR' call for"),
            std::string::npos);
  EXPECT_NE(refusal(fields, "ElementDataFile = LOCAL\n", "x = 3\n").find("is broken (zlib: it calls for a preset "
                                                                          "dictionary"),
            std::string::npos)
      << "the fuzzed header's text after ElementDataFile reads as a zlib header asking for a dictionary";
  EXPECT_NE(refusal(fields, "ElementDataFile = LOCAL\n", zlib_of(std::string(12, '\x07')))
                .find("its compressed data ends after 12 of the 24 bytes"),
            std::string::npos);
}

}  // namespace
}  // namespace grainlab::ct
