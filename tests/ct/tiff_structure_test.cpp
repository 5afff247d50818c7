// grainlab's own walk over a TIFF's structure (ct/tiff_structure.h), before
// ITK's reader: TIFF files built byte by byte here (classic and BigTIFF, both
// byte orders) pass it and are then read by ITK; each way of breaking one
// (a short DateTime, a directory loop, a strip past the end, a short strip,
// a tag twice, an unknown data type, a truncated file) is refused, naming it.
#include "ct_fixture.h"

#include "core/error.h"
#include "ct/itk_bridge.h"
#include "ct/tiff_structure.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

namespace grainlab::ct {
namespace {

namespace fs = std::filesystem;

// A one-page 8-bit greyscale TIFF of width x height pixels in one strip, and the ways to break it.
struct TiffSpec {
  bool big = false;     // BigTIFF: 8-byte offsets and counts
  bool little = true;   // "II" (else "MM")
  std::uint32_t width = 5, height = 3;
  std::string date;     // DateTime, when not empty (with its NUL: 20 bytes for "YYYY:MM:DD HH:MM:SS")
  bool date_nul = true; // DateTime's count takes in its NUL
  std::int64_t strip_offset = -1, strip_bytes = -1;  // -1: where and how long the pixels are
  bool loop = false;    // the next-directory offset points back at the directory
  bool twice = false;   // ImageWidth given twice
  std::uint16_t photometric_type = 3;  // 3 (SHORT); another number breaks the entry's type
};

class Bytes {
 public:
  explicit Bytes(bool little) : little_(little) {}
  void put(std::uint64_t v, int n) {
    for (int i = 0; i < n; ++i) s.push_back(static_cast<char>((v >> (8 * (little_ ? i : n - 1 - i))) & 0xff));
  }
  std::string s;

 private:
  bool little_;
};

std::string make_tiff(const TiffSpec& t) {
  Bytes b(t.little);
  const int word = t.big ? 8 : 4;
  b.s += t.little ? "II" : "MM";
  if (t.big) {
    b.put(43, 2), b.put(8, 2), b.put(0, 2);
  } else {
    b.put(42, 2);
  }
  const std::uint64_t header = t.big ? 16 : 8;
  const std::uint64_t pixels = t.width * t.height;
  const std::uint64_t date_at = header + pixels;
  std::uint64_t ifd = date_at + t.date.size() + 1;
  ifd += ifd % 2;
  b.put(ifd, word);
  for (std::uint64_t i = 0; i < pixels; ++i) b.s.push_back(static_cast<char>(i * 7));
  b.s += t.date;
  b.s.push_back('\0');
  if (b.s.size() < ifd) b.s.push_back('\0');
  struct Entry {
    std::uint16_t tag, type;
    std::uint64_t count, value;
  };
  std::vector<Entry> entries{{256, 4, 1, t.width}, {257, 4, 1, t.height}, {258, 3, 1, 8}, {259, 3, 1, 1},
                             {262, t.photometric_type, 1, 1},
                             {273, 4, 1, t.strip_offset < 0 ? header : static_cast<std::uint64_t>(t.strip_offset)},
                             {277, 3, 1, 1}, {278, 4, 1, t.height},
                             {279, 4, 1, t.strip_bytes < 0 ? pixels : static_cast<std::uint64_t>(t.strip_bytes)}};
  if (t.twice) entries.insert(entries.begin() + 1, {256, 4, 1, t.width});
  if (!t.date.empty()) entries.push_back({306, 2, t.date.size() + (t.date_nul ? 1 : 0), date_at});
  b.put(entries.size(), t.big ? 8 : 2);
  for (const Entry& e : entries) {
    b.put(e.tag, 2), b.put(e.type, 2), b.put(e.count, word);
    const int size = e.type == 3 ? 2 : e.type == 2 ? word : 4;  // SHORT, ASCII (its offset), LONG (others alike)
    b.put(e.value, size);
    b.put(0, word - size);
  }
  b.put(t.loop ? ifd : 0, word);
  return b.s;
}

class TiffStructure : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = testing::fresh_folder(::testing::UnitTest::GetInstance()->current_test_info()->name()); }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path write(const std::string& bytes) {
    const fs::path p = dir_ / "scan.tif";
    std::ofstream(p, std::ios::binary | std::ios::trunc) << bytes;
    return p;
  }
  // The InputError's message checking `bytes` throws ("" if none).
  std::string refusal(const std::string& bytes) {
    try {
      check_tiff_structure(write(bytes));
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }

  fs::path dir_;
};

TEST_F(TiffStructure, WellFormedFilesPassAndItkReadsThem) {
  for (const bool big : {false, true}) {
    for (const bool little : {true, false}) {
      TiffSpec t;
      t.big = big, t.little = little, t.date = "2026:12:06 22:00:00";
      const fs::path p = write(make_tiff(t));
      EXPECT_NO_THROW(check_tiff_structure(p)) << "big " << big << " little " << little;
      const itk_bridge::Header h = itk_bridge::read_header(p.string());
      ASSERT_GE(h.extent.size(), 2u);
      EXPECT_EQ(h.extent[0], 5);
      EXPECT_EQ(h.extent[1], 3);
      const std::vector<float> v = itk_bridge::read_values(p.string());
      ASSERT_EQ(v.size(), 15u);
      EXPECT_EQ(v[14], static_cast<float>(static_cast<std::uint8_t>(14 * 7)));
    }
  }
}

TEST_F(TiffStructure, EachBreakageIsRefusedByName) {
  struct Case {
    void (*breakage)(TiffSpec&);
    const char* message;
  };
  const Case cases[] = {
      {[](TiffSpec& t) { t.date = "2026:12:06 22:00"; },  // 17 bytes with its NUL: ITK copied 20
       "DateTime (tag 306) holds 17 characters up to its first NUL (type 2), fewer than the 20"},
      {[](TiffSpec& t) { t.date = "2026:12:06 22:00:0"; }, "DateTime (tag 306) holds 19 characters"},
      // libtiff keeps the text up to its first NUL: a long count is not enough
      // (tests/fuzz/corpus/tiff/datetime_nul_first_3c98c5ba).
      {[](TiffSpec& t) { t.date = std::string(1, '\0') + "2026:12:06 22:00:00"; },
       "DateTime (tag 306) holds 1 characters up to its first NUL"},
      // Text without its NUL: ITK measured it with strlen past libtiff's
      // buffer (tests/fuzz/corpus/tiff/text_without_nul_da388dbf).
      {[](TiffSpec& t) { t.date = "2026:12:06 22:00:00"; t.date_nul = false; },
       "tag 306 is text (type 2) of 19 bytes that does not end with a NUL"},
      {[](TiffSpec& t) { t.loop = true; }, "comes back to the directory at byte"},
      {[](TiffSpec& t) { t.strip_offset = 1000; }, "strip 1 (15 bytes at byte 1000) lies past the file's end"},
      {[](TiffSpec& t) { t.strip_bytes = 10; }, "uncompressed strip 1 holds 10 bytes, fewer than the 15"},
      {[](TiffSpec& t) { t.twice = true; }, "tag 256 appears twice"},
      {[](TiffSpec& t) { t.photometric_type = 99; }, "tag 262 has data type 99, which TIFF does not define"}};
  for (const Case& c : cases) {
    TiffSpec t;
    c.breakage(t);
    EXPECT_NE(refusal(make_tiff(t)).find(c.message), std::string::npos) << c.message;
  }
  TiffSpec short_date;
  short_date.date = "2026:12:06";
  EXPECT_NE(refusal(make_tiff(short_date)).find("the image may be whole, but ITK reads past such a tag: save the "
                                                "stack again with a tool that writes standard TIFF"),
            std::string::npos)
      << "a writer's non-standard text tag is not called damage, and the fix says what to use";
  const std::string whole = make_tiff(TiffSpec{});
  EXPECT_NE(refusal(whole.substr(0, whole.size() - 20)).find("runs past the file's end"), std::string::npos);
  EXPECT_NE(refusal(std::string("II*\0", 4)).find("fewer than a TIFF header's 8"), std::string::npos);
  EXPECT_NE(refusal("PK\3\4 not a tiff").find("does not start with a TIFF byte order"), std::string::npos);
}

// A classic little-endian TIFF of pages of 8-bit pixels in one strip each:
// per page its width (3 rows) and its NewSubfileType (tag 254; -1: none).
std::string make_pages(const std::vector<std::pair<std::uint32_t, int>>& pages) {
  Bytes b(true);
  b.s += "II";
  b.put(42, 2);
  std::uint64_t at = 8;
  std::vector<std::uint64_t> strips;
  for (const auto& [width, kind] : pages) strips.push_back(at), at += 3 * width;
  at += at % 2;
  b.put(at, 4);
  for (const auto& [width, kind] : pages) b.s.append(3 * width, '\x05');
  if (b.s.size() < at) b.s.push_back('\0');
  for (std::size_t i = 0; i < pages.size(); ++i) {
    const auto [width, kind] = pages[i];
    std::vector<std::array<std::uint32_t, 3>> entries;  // tag, type (3 SHORT, 4 LONG), value
    if (kind >= 0) entries.push_back({254, 4, static_cast<std::uint32_t>(kind)});
    const std::vector<std::array<std::uint32_t, 3>> rest{{256, 4, width}, {257, 4, 3}, {258, 3, 8}, {259, 3, 1},
                                                         {262, 3, 1}, {273, 4, static_cast<std::uint32_t>(strips[i])},
                                                         {277, 3, 1}, {278, 4, 3}, {279, 4, 3 * width}};
    entries.insert(entries.end(), rest.begin(), rest.end());
    b.put(entries.size(), 2);
    for (const auto& [tag, type, value] : entries) b.put(tag, 2), b.put(type, 2), b.put(1, 4), b.put(value, 4);
    at += 2 + 12 * entries.size() + 4;
    b.put(i + 1 < pages.size() ? at : 0, 4);
  }
  return b.s;
}

// ITK sizes a volume from page 1 and its count of full pages, then writes
// each page not marked reduced at its page number: a page of another size or
// of another kind made it write past the image (found by fuzzing:
// tests/fuzz/corpus/tiff/heap_overflow_mixed_subfiles_637afea4).
TEST_F(TiffStructure, PagesOfAnotherSizeOrKindThanTheFirstAreRefused) {
  for (const int kind : {-1, 0, 2}) {
    const fs::path p = write(make_pages({{5, kind}, {5, kind}, {5, kind}}));
    EXPECT_NO_THROW(check_tiff_structure(p)) << "kind " << kind;
    EXPECT_EQ(itk_bridge::read_values(p.string()).size(), 45u) << "kind " << kind << ": three slices of 5 x 3";
  }
  EXPECT_NE(refusal(make_pages({{5, 0}, {6, 0}})).find("page 2): it is 6 x 3 pixels of 1 sample(s) of 8 bits, where "
                                                       "page 1 is 5 x 3"),
            std::string::npos);
  EXPECT_NE(refusal(make_pages({{5, 1}, {5, 0}, {5, 0}})).find("page 2): its subfile type (tags 254, 255) is '254 = "
                                                               "0', where page 1's is '254 = 1'"),
            std::string::npos);
  EXPECT_NE(refusal(make_pages({{5, 2}, {5, -1}})).find("is 'no subfile type', where page 1's is '254 = 2'"),
            std::string::npos);
}

}  // namespace
}  // namespace grainlab::ct
