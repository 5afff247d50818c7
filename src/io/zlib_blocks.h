// VTK's zlib block compression (compressor="vtkZLibDataCompressor") of one
// DataArray's bytes, with the UInt64 header VTK reads before the blocks:
//
//   [number of blocks] [uncompressed block size] [uncompressed size of the
//   last block] [compressed size of block 1] ... [of block n] <blocks>
//
// each an independent zlib stream of up to kZlibBlockSize input bytes. The
// last-block field holds the true size of the last block (VTK reads 0 as "a
// full block", and a full size the same way). An empty array has no blocks.
// Blocks are compressed in parallel; the bytes do not depend on the threads.
// Only tests read them back (tests/io/vtk_decoding.h).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace grainlab {

// Input bytes per zlib block (VTK's readers take any size from the header).
inline constexpr std::size_t kZlibBlockSize = std::size_t(1) << 18;

// Appends the header and the compressed blocks of `bytes` to `out`.
void append_zlib_blocks(std::string& out, std::span<const std::uint8_t> bytes);

}  // namespace grainlab
