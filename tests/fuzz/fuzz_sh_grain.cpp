// Fuzz harness: a spherical-harmonic grain file (grains/sh_grain.h:
// load_sh_grain reads the coefficients, checks them and meshes the grain,
// here with 80 faces to keep each execution short). See harness_input.h.
#include "fuzz/harness_input.h"
#include "grains/sh_grain.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path = grainlab::fuzz::input_file({data, size}, "grain.dat");
  return grainlab::fuzz::refused_or_read([&] { grainlab::load_sh_grain(path, 80, grainlab::ShOptions{}); });
}
