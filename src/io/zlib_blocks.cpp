// VTK's zlib block compression (see zlib_blocks.h).
#include "io/zlib_blocks.h"

#include "core/parallel.h"

#include <fmt/format.h>
#include <zlib.h>

#include <bit>
#include <cstring>
#include <stdexcept>

namespace grainlab {

static_assert(std::endian::native == std::endian::little, "the zlib block header is written little-endian");

namespace {

// zlib level 6 (its default): within a few per cent of level 9 on snapshot
// arrays, several times faster.
constexpr int kLevel = 6;

void append_u64(std::string& out, std::uint64_t v) {
  char b[8];
  std::memcpy(b, &v, 8);
  out.append(b, 8);
}

std::uint64_t read_u64(std::string_view data, std::size_t at) {
  std::uint64_t v;
  std::memcpy(&v, data.data() + at, 8);
  return v;
}

}  // namespace

void append_zlib_blocks(std::string& out, std::span<const std::uint8_t> bytes) {
  const std::size_t n = bytes.size();
  const std::size_t blocks = (n + kZlibBlockSize - 1) / kZlibBlockSize;
  std::vector<std::vector<std::uint8_t>> packed(blocks);
  std::vector<char> failed(blocks, 0);  // no exception may leave a parallel loop
  parallel_for(
      static_cast<std::ptrdiff_t>(blocks),
      [&](std::ptrdiff_t b) {
        const std::size_t begin = static_cast<std::size_t>(b) * kZlibBlockSize;
        const std::size_t size = std::min(kZlibBlockSize, n - begin);
        std::vector<std::uint8_t>& dst = packed[b];
        uLongf len = compressBound(static_cast<uLong>(size));
        dst.resize(len);
        failed[b] = compress2(dst.data(), &len, bytes.data() + begin, static_cast<uLong>(size), kLevel) != Z_OK;
        dst.resize(len);
      },
      1);
  for (const char f : failed)
    if (f) throw std::runtime_error("zlib could not compress a block of a VTK array (out of memory?)");
  append_u64(out, blocks);
  append_u64(out, kZlibBlockSize);
  append_u64(out, blocks ? n - (blocks - 1) * kZlibBlockSize : 0);
  for (const auto& p : packed) append_u64(out, p.size());
  for (const auto& p : packed) out.append(reinterpret_cast<const char*>(p.data()), p.size());
}

std::vector<std::uint8_t> read_zlib_blocks(std::string_view data, std::size_t& used) {
  if (data.size() < 24) throw std::invalid_argument("the zlib block header is cut short");
  const std::uint64_t blocks = read_u64(data, 0), block_size = read_u64(data, 8), last = read_u64(data, 16);
  if (blocks > data.size() / 8 || (blocks > 0 && (block_size == 0 || last > block_size)))
    throw std::invalid_argument(fmt::format("the zlib block header is damaged ({} blocks of {} bytes, the last {})",
                                            blocks, block_size, last));
  std::size_t at = 24 + 8 * blocks;
  if (data.size() < at) throw std::invalid_argument("the zlib block sizes are cut short");
  const std::uint64_t total = blocks == 0 ? 0 : (blocks - 1) * block_size + (last ? last : block_size);
  std::vector<std::uint8_t> out(total);
  std::size_t written = 0;
  for (std::uint64_t b = 0; b < blocks; ++b) {
    const std::uint64_t csize = read_u64(data, 24 + 8 * b);
    const std::uint64_t expect = b + 1 < blocks ? block_size : total - written;
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
