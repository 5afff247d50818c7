#include "ct/tiff_structure.h"

#include "core/error.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace grainlab::ct {

namespace fs = std::filesystem;

namespace {

constexpr std::uint64_t kMaxPages = 1000000;
constexpr std::uint64_t kMaxSide = 1u << 20;
constexpr std::uint64_t kMaxEntries = 4096;

enum Tag : std::uint16_t {
  kNewSubfileType = 254, kSubfileType = 255, kWidth = 256, kLength = 257, kBitsPerSample = 258, kCompression = 259,
  kStripOffsets = 273,
  kSamplesPerPixel = 277, kRowsPerStrip = 278, kStripByteCounts = 279, kPlanar = 284, kDateTime = 306,
  kTileWidth = 322, kTileLength = 323, kTileOffsets = 324, kTileByteCounts = 325
};

// Bytes of one value of TIFF data type `type`; 0 for an unknown type.
std::uint64_t type_bytes(std::uint16_t type) {
  static const std::map<std::uint16_t, std::uint64_t> bytes = {
      {1, 1}, {2, 1}, {3, 2}, {4, 4}, {5, 8}, {6, 1}, {7, 1}, {8, 2}, {9, 4}, {10, 8}, {11, 4}, {12, 8}, {13, 4},
      {16, 8}, {17, 8}, {18, 8}};
  const auto it = bytes.find(type);
  return it == bytes.end() ? 0 : it->second;
}

struct Entry {
  std::uint16_t type = 0;
  std::uint64_t count = 0;
  std::uint64_t at = 0;  // where the values are: in the entry, or at its offset
};

class TiffWalk {
 public:
  explicit TiffWalk(const fs::path& path) : path_(path), in_(path, std::ios::binary) {
    std::error_code ec;
    size_ = fs::file_size(path, ec);
    if (ec || !in_) input_error("cannot read '{}': {}", path.string(), ec ? ec.message() : "cannot open it");
  }

  void check() {
    std::uint8_t magic[4] = {0, 0, 0, 0};
    if (size_ < 8) fail("the file holds {} bytes, fewer than a TIFF header's 8", size_);
    read(0, magic, 4);
    if ((magic[0] != 'I' || magic[1] != 'I') && (magic[0] != 'M' || magic[1] != 'M')) {
      fail("it does not start with a TIFF byte order ('II' or 'MM')");
    }
    little_ = magic[0] == 'I';
    const std::uint16_t version = u16(2);
    if (version == 43) {
      big_ = true;
      if (size_ < 16 || u16(4) != 8 || u16(6) != 0) fail("a BigTIFF header that is not 8-byte offsets");
    } else if (version != 42) {
      fail("its version is {}, where a TIFF has 42 (or 43: BigTIFF)", version);
    }
    std::uint64_t ifd = big_ ? u64(8) : u32(4);
    std::set<std::uint64_t> seen;
    for (page_ = 0; ifd != 0; ++page_) {
      if (static_cast<std::uint64_t>(page_) == kMaxPages) fail("more than {} pages", kMaxPages);
      if (!seen.insert(ifd).second) fail("its directory chain comes back to the directory at byte {} (a loop)", ifd);
      ifd = check_page(ifd);
    }
  }

 private:
  template <typename... Args>
  [[noreturn]] void fail(fmt::format_string<Args...> f, Args&&... args) const {
    refuse(fmt::format(f, std::forward<Args>(args)...), "the file is damaged or not a TIFF: export the scan again");
  }
  // A text tag TIFF's rules forbid, in a file whose image may be whole (some
  // writers leave the NUL out or shorten DateTime): ITK cannot read it safely.
  template <typename... Args>
  [[noreturn]] void fail_text(fmt::format_string<Args...> f, Args&&... args) const {
    refuse(fmt::format(f, std::forward<Args>(args)...),
           "the image may be whole, but ITK reads past such a tag: save the stack again with a tool that writes "
           "standard TIFF (Fiji: File > Save As > Tiff...) or convert it to NRRD or MetaImage");
  }
  [[noreturn]] void refuse(const std::string& what, const char* fix) const {
    const std::string where = page_ < 0 ? "" : fmt::format(", page {}", page_ + 1);
    input_error("'{}' (TIFF{}): {}; {}", path_.string(), where, what, fix);
  }

  void read(std::uint64_t at, void* out, std::uint64_t n) {
    if (at > size_ || n > size_ - at) fail("a read of {} bytes at byte {} lies past its end ({} bytes)", n, at, size_);
    in_.seekg(static_cast<std::streamoff>(at));
    in_.read(static_cast<char*>(out), static_cast<std::streamsize>(n));
    if (!in_) fail("it could not be read at byte {}", at);
  }
  std::uint64_t uint(std::uint64_t at, int bytes) {
    std::array<std::uint8_t, 8> b{};
    read(at, b.data(), static_cast<std::uint64_t>(bytes));
    std::uint64_t v = 0;
    for (int i = 0; i < bytes; ++i) v |= std::uint64_t{b[static_cast<std::size_t>(little_ ? i : bytes - 1 - i)]} << (8 * i);
    return v;
  }
  std::uint16_t u16(std::uint64_t at) { return static_cast<std::uint16_t>(uint(at, 2)); }
  std::uint32_t u32(std::uint64_t at) { return static_cast<std::uint32_t>(uint(at, 4)); }
  std::uint64_t u64(std::uint64_t at) { return uint(at, 8); }

  // The entries of the IFD at `ifd`, each checked; returns the next IFD's offset.
  std::uint64_t read_entries(std::uint64_t ifd, std::map<std::uint16_t, Entry>& entries) {
    const std::uint64_t count_bytes = big_ ? 8 : 2, entry_bytes = big_ ? 20 : 12, inline_bytes = big_ ? 8 : 4;
    const std::uint64_t n = big_ ? u64(ifd) : u16(ifd);
    if (n == 0 || n > kMaxEntries) fail("its directory at byte {} has {} entries (1 to {} make sense)", ifd, n, kMaxEntries);
    const std::uint64_t first = ifd + count_bytes;
    if (first > size_ || n * entry_bytes + inline_bytes > size_ - first) {
      fail("its directory at byte {} ({} entries) runs past the file's end", ifd, n);
    }
    for (std::uint64_t i = 0; i < n; ++i) {
      const std::uint64_t e = first + i * entry_bytes;
      const std::uint16_t tag = u16(e);
      Entry entry;
      entry.type = u16(e + 2);
      entry.count = big_ ? u64(e + 4) : u32(e + 4);
      const std::uint64_t value = e + (big_ ? 12 : 8);
      const std::uint64_t size = type_bytes(entry.type);
      if (size == 0) fail("tag {} has data type {}, which TIFF does not define", tag, entry.type);
      if (entry.count > size_ / size) fail("tag {} claims {} values, more than the file's {} bytes hold", tag, entry.count, size_);
      const std::uint64_t bytes = entry.count * size;
      entry.at = bytes <= inline_bytes ? value : (big_ ? u64(value) : u32(value));
      if (entry.at > size_ || bytes > size_ - entry.at) {
        fail("the {} bytes of tag {} at byte {} lie past the file's end ({} bytes)", bytes, tag, entry.at, size_);
      }
      if (entry.type == 2) check_text_ends(tag, entry);
      if (tag == kDateTime) check_date_time(entry);
      if (!entries.emplace(tag, entry).second) fail("tag {} appears twice in one directory", tag);
    }
    const std::uint64_t next = first + n * entry_bytes;
    return big_ ? u64(next) : u32(next);
  }

  // TIFF text (type 2) ends with a NUL. libtiff keeps the bytes of a tag it
  // does not know as they are, and ITK measured them with strlen: a text
  // without its NUL made it read past libtiff's buffer (found by fuzzing).
  void check_text_ends(std::uint16_t tag, const Entry& e) {
    std::uint8_t last = 1;
    if (e.count > 0) read(e.at + e.count - 1, &last, 1);
    if (last != 0) {
      fail_text("tag {} is text (type 2) of {} bytes that does not end with a NUL, as TIFF text must", tag, e.count);
    }
  }

  // ITK copies DateTime's 20 bytes ("YYYY:MM:DD HH:MM:SS" and a NUL, as TIFF
  // fixes it) out of what libtiff keeps: the text up to its first NUL, and a
  // NUL. Fewer made ITK read past libtiff's buffer (found by fuzzing: a short
  // count, then a long count whose first byte is a NUL).
  void check_date_time(const Entry& e) {
    std::array<std::uint8_t, 20> text{};
    const std::uint64_t n = e.type == 2 ? std::min<std::uint64_t>(e.count, text.size()) : 0;
    read(e.at, text.data(), n);
    std::uint64_t chars = 0;
    while (chars < n && text[chars] != 0) ++chars;
    const std::uint64_t held = chars + 1;
    if (e.type != 2 || held < 20) {
      fail_text("its DateTime (tag 306) holds {} characters up to its first NUL (type {}), fewer than the 20 TIFF fixes "
           "('YYYY:MM:DD HH:MM:SS' and a NUL)", e.type == 2 ? held : 0, e.type);
    }
  }

  // The tag's values as whole numbers (BYTE, SHORT, LONG, LONG8 and IFD types).
  std::vector<std::uint64_t> values(const std::map<std::uint16_t, Entry>& entries, std::uint16_t tag) {
    const Entry& e = entries.at(tag);
    const std::uint64_t size = type_bytes(e.type);
    if (e.type != 1 && e.type != 3 && e.type != 4 && e.type != 13 && e.type != 16 && e.type != 18) {
      fail("tag {} has data type {}, where an unsigned whole number is needed", tag, e.type);
    }
    std::vector<std::uint8_t> raw(e.count * size);  // inside the file: read_entries checked it
    read(e.at, raw.data(), raw.size());
    std::vector<std::uint64_t> out(e.count, 0);
    for (std::uint64_t i = 0; i < e.count; ++i) {
      for (std::uint64_t b = 0; b < size; ++b) {
        out[i] |= std::uint64_t{raw[i * size + (little_ ? b : size - 1 - b)]} << (8 * b);
      }
    }
    return out;
  }

  std::uint64_t single(const std::map<std::uint16_t, Entry>& entries, std::uint16_t tag, const char* name,
                       std::uint64_t fallback, std::uint64_t lowest, std::uint64_t highest) {
    if (!entries.count(tag)) return fallback;
    const std::vector<std::uint64_t> v = values(entries, tag);
    if (v.empty()) fail("its {} (tag {}) holds no value", name, tag);
    if (v[0] < lowest || v[0] > highest) fail("its {} (tag {}) is {}, outside {} to {}", name, tag, v[0], lowest, highest);
    return v[0];
  }

  // ITK reads a file of several pages as a volume: it sizes the image from
  // the first page and the number of full-resolution pages (NewSubfileType 0),
  // then writes every page not marked reduced or mask at its page number. A
  // page of another size, or pages of mixed kinds (a full page after a
  // reduced one, kinds 0 and 2 mixed, an old SubfileType on some), made it
  // write past the image (found by fuzzing: a heap overflow in
  // TIFFImageIO::ReadGenericImage). So every page must be the first page's
  // size and of its kind: the slices of one scan.
  struct Page {
    std::uint64_t width, length, samples, bits;
  };
  void check_like_the_first_page(const std::map<std::uint16_t, Entry>& entries, const Page& page) {
    const auto kind = [&](std::uint16_t tag) {
      return entries.count(tag) ? fmt::format("{} = {}", tag, single(entries, tag, "SubfileType", 0, 0, UINT64_MAX))
                                : std::string();
    };
    const bool both = entries.count(kSubfileType) && entries.count(kNewSubfileType);
    std::string kinds = kind(kNewSubfileType) + (both ? ", " : "") + kind(kSubfileType);
    if (kinds.empty()) kinds = "no subfile type";
    if (page_ == 0) {
      first_ = page;
      first_kinds_ = kinds;
      return;
    }
    if (page.width != first_.width || page.length != first_.length || page.samples != first_.samples ||
        page.bits != first_.bits) {
      fail("it is {} x {} pixels of {} sample(s) of {} bits, where page 1 is {} x {} of {} of {}: the slices of a "
           "volume are all one size",
           page.width, page.length, page.samples, page.bits, first_.width, first_.length, first_.samples, first_.bits);
    }
    if (kinds != first_kinds_) {
      fail("its subfile type (tags 254, 255) is '{}', where page 1's is '{}': a volume's pages are all slices of one "
           "kind (ITK reads mixed kinds past its image); keep only the scan's slices",
           kinds, first_kinds_);
    }
  }

  std::uint64_t check_page(std::uint64_t ifd) {
    std::map<std::uint16_t, Entry> entries;
    const std::uint64_t next = read_entries(ifd, entries);
    if (!entries.count(kWidth) || !entries.count(kLength)) fail("no ImageWidth (256) or ImageLength (257) tag");
    const std::uint64_t width = single(entries, kWidth, "ImageWidth", 0, 1, kMaxSide);
    const std::uint64_t length = single(entries, kLength, "ImageLength", 0, 1, kMaxSide);
    const std::uint64_t samples = single(entries, kSamplesPerPixel, "SamplesPerPixel", 1, 1, 16);
    const std::uint64_t planar = single(entries, kPlanar, "PlanarConfiguration", 1, 1, 2);
    const std::uint64_t compression = single(entries, kCompression, "Compression", 1, 1, 65535);
    std::uint64_t bits = 1;
    if (entries.count(kBitsPerSample)) {
      const std::vector<std::uint64_t> b = values(entries, kBitsPerSample);
      if (b.empty()) fail("its BitsPerSample (tag 258) holds no value");
      for (const std::uint64_t v : b) {
        if (v < 1 || v > 64) fail("its BitsPerSample (tag 258) is {}, outside 1 to 64", v);
      }
      bits = b[0];
    }
    const std::uint64_t planes = planar == 2 ? samples : 1;
    const std::uint64_t pixel_bits = bits * (planar == 2 ? 1 : samples);
    const bool tiled = entries.count(kTileOffsets) || entries.count(kTileWidth);
    std::uint64_t across = 1, down = 0, block_width = width, block_rows = 0;
    const char* offsets_name = tiled ? "TileOffsets" : "StripOffsets";
    const std::uint16_t offsets_tag = tiled ? kTileOffsets : kStripOffsets;
    const std::uint16_t counts_tag = tiled ? kTileByteCounts : kStripByteCounts;
    if (tiled) {
      block_width = single(entries, kTileWidth, "TileWidth", 0, 1, kMaxSide);
      block_rows = single(entries, kTileLength, "TileLength", 0, 1, kMaxSide);
      if (block_width == 0 || block_rows == 0) fail("tiles without TileWidth (322) or TileLength (323)");
      across = (width + block_width - 1) / block_width;
    } else {
      block_rows = std::min(single(entries, kRowsPerStrip, "RowsPerStrip", UINT32_MAX, 1, UINT64_MAX), length);
    }
    down = (length + block_rows - 1) / block_rows;
    const std::uint64_t blocks = across * down * planes;
    if (!entries.count(offsets_tag) || !entries.count(counts_tag)) {
      fail("no {} ({}) or its byte counts ({}): where its pixels are is not said", offsets_name, offsets_tag, counts_tag);
    }
    const std::vector<std::uint64_t> offsets = values(entries, offsets_tag);
    const std::vector<std::uint64_t> counts = values(entries, counts_tag);
    if (offsets.size() != blocks || counts.size() != blocks) {
      fail("{} {} offsets and {} byte counts, where a {} x {} image of these {} needs {}", tiled ? "its" : "its",
           offsets.size(), counts.size(), width, length, tiled ? "tiles" : "strips", blocks);
    }
    check_like_the_first_page(entries, {width, length, samples, bits});
    const std::uint64_t row_bytes = (block_width * pixel_bits + 7) / 8;
    for (std::uint64_t i = 0; i < blocks; ++i) {
      if (offsets[i] > size_ || counts[i] > size_ - offsets[i]) {
        fail("{} {} ({} bytes at byte {}) lies past the file's end ({} bytes)", tiled ? "tile" : "strip", i + 1,
             counts[i], offsets[i], size_);
      }
      const std::uint64_t rows = tiled ? block_rows : std::min(block_rows, length - (i % down) * block_rows);
      if (compression == 1 && counts[i] < rows * row_bytes) {
        fail("uncompressed {} {} holds {} bytes, fewer than the {} its pixels take", tiled ? "tile" : "strip", i + 1,
             counts[i], rows * row_bytes);
      }
    }
    return next;
  }

  fs::path path_;
  std::ifstream in_;
  std::uint64_t size_ = 0;
  bool little_ = true;
  bool big_ = false;
  std::int64_t page_ = -1;
  Page first_{};
  std::string first_kinds_;
};

}  // namespace

void check_tiff_structure(const fs::path& path) { TiffWalk(path).check(); }

}  // namespace grainlab::ct
