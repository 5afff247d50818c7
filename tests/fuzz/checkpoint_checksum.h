// A checkpoint's bytes with the size and checksum fields of its header made
// to agree with its payload, so that a fuzzed payload reaches the decoder
// instead of the checksum's refusal. Layout (io/checkpoint.cpp): 8 bytes of
// signature, u32 version, u32 grains, u64 payload size, u64 FNV-1a checksum
// of the payload (little endian), then the payload from byte 32.
#pragma once

#include "io/checkpoint.h"

#include <cstdint>
#include <span>
#include <vector>

namespace grainlab::fuzz {

inline std::vector<std::uint8_t> with_right_checksum(std::vector<std::uint8_t> bytes) {
  constexpr std::size_t kHeader = 32;
  if (bytes.size() < kHeader) return bytes;
  const auto put_u64 = [&](std::size_t at, std::uint64_t v) {
    for (int i = 0; i < 8; ++i) bytes[at + i] = static_cast<std::uint8_t>(v >> (8 * i));
  };
  put_u64(16, bytes.size() - kHeader);
  put_u64(24, fnv1a64(std::span<const std::uint8_t>(bytes).subspan(kHeader)));
  return bytes;
}

}  // namespace grainlab::fuzz
