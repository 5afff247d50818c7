// Base64 (RFC 4648, standard alphabet, '=' padding) for the binary arrays of
// VTK XML files. Only tests decode (tests/io/vtk_decoding.h, which checks
// decode(encode(b)) == b for any bytes).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace grainlab {

// The base64 text of `bytes`: 4 characters per 3 bytes, the last group padded with '='.
std::string base64_encode(std::span<const std::uint8_t> bytes);

// Appends the base64 text of `bytes` to `out` (no separator).
void base64_append(std::string& out, std::span<const std::uint8_t> bytes);

// Number of base64 characters that encode n bytes (padding included).
constexpr std::size_t base64_length(std::size_t n) { return (n + 2) / 3 * 4; }

}  // namespace grainlab
