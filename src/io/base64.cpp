// Base64 encoding (see base64.h).
#include "io/base64.h"


namespace grainlab {

namespace {

constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

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

}  // namespace grainlab
