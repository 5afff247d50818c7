// Base64 encoding and decoding (see base64.h).
#include "io/base64.h"

#include <array>
#include <stdexcept>

namespace grainlab {

namespace {

constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

// Value of each character: 0..63, or -1 outside the alphabet.
constexpr std::array<int, 256> decode_table() {
  std::array<int, 256> t{};
  for (int& v : t) v = -1;
  for (int i = 0; i < 64; ++i) t[static_cast<unsigned char>(kAlphabet[i])] = i;
  return t;
}
constexpr std::array<int, 256> kDecode = decode_table();

bool is_space(char c) { return c == ' ' || c == '\n' || c == '\r' || c == '\t'; }

}  // namespace

void base64_append(std::string& out, std::span<const std::uint8_t> bytes) {
  const std::size_t n = bytes.size();
  const std::size_t start = out.size();
  out.resize(start + base64_length(n));
  char* o = out.data() + start;
  const std::uint8_t* b = bytes.data();
  std::size_t i = 0;
  for (; i + 3 <= n; i += 3, o += 4) {
    const std::uint32_t g = (std::uint32_t{b[i]} << 16) | (std::uint32_t{b[i + 1]} << 8) | b[i + 2];
    o[0] = kAlphabet[(g >> 18) & 63];
    o[1] = kAlphabet[(g >> 12) & 63];
    o[2] = kAlphabet[(g >> 6) & 63];
    o[3] = kAlphabet[g & 63];
  }
  if (const std::size_t rest = n - i; rest > 0) {
    std::uint32_t g = std::uint32_t{b[i]} << 16;
    if (rest == 2) g |= std::uint32_t{b[i + 1]} << 8;
    o[0] = kAlphabet[(g >> 18) & 63];
    o[1] = kAlphabet[(g >> 12) & 63];
    o[2] = rest == 2 ? kAlphabet[(g >> 6) & 63] : '=';
    o[3] = '=';
  }
}

std::string base64_encode(std::span<const std::uint8_t> bytes) {
  std::string out;
  base64_append(out, bytes);
  return out;
}

std::vector<std::uint8_t> base64_decode(std::string_view text) {
  std::vector<std::uint8_t> out;
  out.reserve(text.size() / 4 * 3);
  int quad[4];
  int have = 0;       // characters in the current group
  int padding = 0;    // '=' seen in the current group
  bool ended = false; // a padded group closed the data
  for (const char c : text) {
    if (is_space(c)) continue;
    if (ended) throw std::invalid_argument("base64: data after the final padded group");
    if (c == '=') {
      if (have < 2) throw std::invalid_argument("base64: '=' too early in a group of 4");
      quad[have++] = 0;
      ++padding;
    } else {
      const int v = kDecode[static_cast<unsigned char>(c)];
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

}  // namespace grainlab
