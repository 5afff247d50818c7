// Fuzz harness: a run's TOML config (io/config.h: parse_config, which parses,
// matches every key to a field, checks lengths and validates the values).
// See harness_input.h.
#include "fuzz/harness_input.h"
#include "io/config.h"

#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  return grainlab::fuzz::refused_or_read([&] { grainlab::parse_config(text, "fuzz.toml"); });
}
