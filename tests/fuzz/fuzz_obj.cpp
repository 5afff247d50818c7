// Fuzz harness: a Wavefront OBJ file through load_mesh, as a grain's mesh file reaches
// grainlab (geometry/mesh_check.h: read_mesh with its bounds, then the
// checks and repairs). assimp parses the format; what is fuzzed is
// grainlab's wrapper around it: its size bounds, the checks of what assimp
// returns, and the repairs. See harness_input.h.
#include "fuzz/harness_input.h"
#include "geometry/mesh_check.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path = grainlab::fuzz::input_file({data, size}, "input.obj");
  return grainlab::fuzz::refused_or_read([&] { grainlab::load_mesh(path); });
}
