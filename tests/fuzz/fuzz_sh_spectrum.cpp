// Fuzz harness: a sand's spectrum file (io/sh_spectrum_file.h), the TOML
// that `grainlab grains generate --spectrum` reads. See harness_input.h.
#include "fuzz/harness_input.h"
#include "io/sh_spectrum_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path = grainlab::fuzz::input_file({data, size}, "spectrum.toml");
  return grainlab::fuzz::refused_or_read([&] { grainlab::read_sh_spectrum(path); });
}
