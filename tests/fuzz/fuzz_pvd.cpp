// Fuzz harness: a ParaView collection (.pvd) that a resumed run reads back to
// go on appending (io/pvd_reader.h, on io/xml_scanner.h). See harness_input.h.
#include "fuzz/harness_input.h"
#include "io/pvd_reader.h"

#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  return grainlab::fuzz::refused_or_read([&] { grainlab::parse_pvd(text, "fuzz.pvd"); });
}
