// A check of compressed scan data before a third-party reader sees it.
// ITK's MetaIO inflates a compressed MetaImage until the image is full and
// loops for ever when the stream breaks or ends first (found by fuzzing: a
// header naming text as its zlib data hung `ct segment`). So grainlab
// inflates the stream itself first, into a scratch buffer, until `need` bytes
// come out: a stream that yields fewer is refused.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

namespace grainlab::ct {

struct InflatedPrefix {
  std::uint64_t produced = 0;  // bytes the stream gave, at most `need`
  std::string error;           // zlib's reason when the stream broke, "" when it ended or gave `need`
};

// Inflates the zlib or gzip stream starting at byte `offset` of `file` (of
// `stream_bytes` bytes at most; 0: up to the file's end) until `need` bytes
// come out, the stream ends, or it breaks.
InflatedPrefix inflate_prefix(const std::filesystem::path& file, std::uint64_t offset, std::uint64_t stream_bytes,
                              std::uint64_t need);

}  // namespace grainlab::ct
