#include "ct/compressed_data.h"

#include <zlib.h>

#include <algorithm>
#include <array>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

namespace grainlab::ct {

InflatedPrefix inflate_prefix(const std::filesystem::path& file, std::uint64_t offset, std::uint64_t stream_bytes,
                              std::uint64_t need) {
  InflatedPrefix out;
  std::ifstream in(file, std::ios::binary);
  in.seekg(static_cast<std::streamoff>(offset));
  if (!in) return out;
  z_stream z{};
  if (inflateInit2(&z, 15 + 32) != Z_OK) {  // 15 + 32: a zlib or a gzip header, as MetaIO takes
    out.error = "zlib could not start";
    return out;
  }
  std::uint64_t left = stream_bytes == 0 ? std::numeric_limits<std::uint64_t>::max() : stream_bytes;
  std::vector<unsigned char> input(1 << 16), scratch(1 << 16);
  int status = Z_OK;
  while (out.produced < need && status != Z_STREAM_END) {
    if (z.avail_in == 0) {
      if (left == 0 || !in) break;
      in.read(reinterpret_cast<char*>(input.data()),
              static_cast<std::streamsize>(std::min<std::uint64_t>(input.size(), left)));
      const auto got = static_cast<std::uint64_t>(in.gcount());
      if (got == 0) break;
      left -= got;
      z.next_in = input.data();
      z.avail_in = static_cast<uInt>(got);
    }
    z.next_out = scratch.data();
    z.avail_out = static_cast<uInt>(std::min<std::uint64_t>(scratch.size(), need - out.produced));
    const uInt before = z.avail_out;
    status = inflate(&z, Z_NO_FLUSH);
    out.produced += before - z.avail_out;
    if (status != Z_OK && status != Z_STREAM_END && status != Z_BUF_ERROR) {
      out.error = status == Z_NEED_DICT ? "it calls for a preset dictionary, which scan data does not use"
                  : z.msg != nullptr    ? z.msg
                                        : "zlib error " + std::to_string(status);
      break;
    }
    if (status == Z_BUF_ERROR && z.avail_in != 0) break;  // no progress with input left: cannot go on
  }
  inflateEnd(&z);
  return out;
}

}  // namespace grainlab::ct
