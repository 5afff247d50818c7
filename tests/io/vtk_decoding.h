// Test helper: the inverses of what io/ writes into VTK files, base64
// (io/base64.h) and VTK's zlib blocks (io/zlib_blocks.h), so that tests can
// read back the bytes a run wrote (only tests read them: the engine reads
// .pvd collections only). Header-only: test_io and test_apps both use it
// (through vtp_reader.h).
#pragma once

#include <fmt/format.h>
#include <zlib.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace grainlab {

namespace decoding {

// Value of each base64 character (RFC 4648, standard alphabet): 0..63, or -1 outside the alphabet.
constexpr std::array<int, 256> base64_values() {
  constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::array<int, 256> t{};
  for (int& v : t) v = -1;
  for (int i = 0; i < 64; ++i) t[static_cast<unsigned char>(kAlphabet[i])] = i;
  return t;
}
inline constexpr std::array<int, 256> kBase64Values = base64_values();

inline bool is_space(char c) { return c == ' ' || c == '\n' || c == '\r' || c == '\t'; }

inline std::uint64_t read_u64(std::string_view data, std::size_t at) {
  std::uint64_t v;
  std::memcpy(&v, data.data() + at, 8);
  return v;
}

}  // namespace decoding

// The bytes of base64 `text`. Whitespace is skipped; anything else outside the
// alphabet, a length that is not a multiple of 4, or padding before the end
// throws std::invalid_argument.
inline std::vector<std::uint8_t> base64_decode(std::string_view text) {
  std::vector<std::uint8_t> out;
  out.reserve(text.size() / 4 * 3);
  int quad[4];
  int have = 0;       // characters in the current group
  int padding = 0;    // '=' seen in the current group
  bool ended = false; // a padded group closed the data
  for (const char c : text) {
    if (decoding::is_space(c)) continue;
    if (ended) throw std::invalid_argument("base64: data after the final padded group");
    if (c == '=') {
      if (have < 2) throw std::invalid_argument("base64: '=' too early in a group of 4");
      quad[have++] = 0;
      ++padding;
    } else {
      const int v = decoding::kBase64Values[static_cast<unsigned char>(c)];
      if (v < 0) throw std::invalid_argument(std::string("base64: invalid character '") + c + "'");
      if (padding > 0) throw std::invalid_argument("base64: character after '=' padding");
      quad[have++] = v;
    }
    if (have == 4) {
      const std::uint32_t g = (std::uint32_t(quad[0]) << 18) | (std::uint32_t(quad[1]) << 12) |
                              (std::uint32_t(quad[2]) << 6) | std::uint32_t(quad[3]);
      out.push_back(static_cast<std::uint8_t>(g >> 16));
      if (padding < 2) out.push_back(static_cast<std::uint8_t>(g >> 8));
      if (padding < 1) out.push_back(static_cast<std::uint8_t>(g));
      ended = padding > 0;
      have = 0;
      padding = 0;
    }
  }
  if (have != 0) throw std::invalid_argument("base64: length is not a multiple of 4");
  return out;
}

// The bytes of the zlib block header and blocks that start `data` (trailing
// data is allowed); `used` gets how many bytes of `data` they took. Throws
// std::invalid_argument saying what is wrong for a damaged or truncated stream.
inline std::vector<std::uint8_t> read_zlib_blocks(std::string_view data, std::size_t& used) {
  if (data.size() < 24) throw std::invalid_argument("the zlib block header is cut short");
  const std::uint64_t blocks = decoding::read_u64(data, 0), block_size = decoding::read_u64(data, 8), last = decoding::read_u64(data, 16);
  if (blocks > data.size() / 8 || (blocks > 0 && (block_size == 0 || last > block_size)))
    throw std::invalid_argument(fmt::format("the zlib block header is damaged ({} blocks of {} bytes, the last {})",
                                            blocks, block_size, last));
  std::size_t at = 24 + 8 * blocks;
  if (data.size() < at) throw std::invalid_argument("the zlib block sizes are cut short");
  // Each block's size against its compressed bytes before anything is
  // allocated: deflate packs at most 1032 bytes into one, so a header that
  // claims more than its blocks can hold is damaged (it once allocated what a
  // 2 kB file claimed: 7.6 EB).
  const auto block_bytes = [&](std::uint64_t b) { return b + 1 < blocks || last == 0 ? block_size : last; };
  std::uint64_t total = 0, packed = 0;
  for (std::uint64_t b = 0; b < blocks; ++b) {
    const std::uint64_t csize = decoding::read_u64(data, 24 + 8 * b);
    if (csize > data.size() - at - packed)
      throw std::invalid_argument(fmt::format("zlib block {} of {} is cut short", b + 1, blocks));
    if (block_bytes(b) / 1032 > csize)
      throw std::invalid_argument(fmt::format("zlib block {} of {} claims {} bytes, more than its {} compressed bytes "
                                              "can hold",
                                              b + 1, blocks, block_bytes(b), csize));
    packed += csize;
    total += block_bytes(b);
  }
  std::vector<std::uint8_t> out(total);
  std::size_t written = 0;
  for (std::uint64_t b = 0; b < blocks; ++b) {
    const std::uint64_t csize = decoding::read_u64(data, 24 + 8 * b);
    const std::uint64_t expect = block_bytes(b);
    if (csize > data.size() - at)
      throw std::invalid_argument(fmt::format("zlib block {} of {} is cut short", b + 1, blocks));
    uLongf len = static_cast<uLongf>(expect);
    const int rc = uncompress(out.data() + written, &len, reinterpret_cast<const Bytef*>(data.data() + at),
                              static_cast<uLong>(csize));
    if (rc != Z_OK || len != expect)
      throw std::invalid_argument(fmt::format("zlib block {} of {} does not decompress to {} bytes ({})", b + 1,
                                              blocks, expect, rc == Z_OK ? "wrong size" : zError(rc)));
    at += csize;
    written += expect;
  }
  used = at;
  return out;
}

}  // namespace grainlab
