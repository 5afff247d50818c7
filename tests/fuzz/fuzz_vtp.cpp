// Fuzz harness: the .vtp reader (tests/io/vtp_reader.h: inline base64 and
// appended raw or zlib-compressed arrays, on io/xml_scanner.h,
// io/base64.h and io/zlib_blocks.h). See harness_input.h.
#include "fuzz/harness_input.h"
#include "io/vtp_reader.h"

#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  return grainlab::fuzz::refused_or_read([&] { grainlab::parse_vtp(text, "fuzz.vtp"); });
}
