// Fuzz harness: a PLY file (ASCII or binary) through load_mesh, as a grain's mesh file reaches
// grainlab (geometry/mesh_check.h: read_mesh with its bounds, then the
// checks and repairs). grainlab's own reader parses the format
// (geometry/ply_reader.h): its header checks, its bounds on every count, the
// triangulation, then the merge and the repairs are fuzzed. See harness_input.h.
#include "fuzz/harness_input.h"
#include "geometry/mesh_check.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path = grainlab::fuzz::input_file({data, size}, "input.ply");
  return grainlab::fuzz::refused_or_read([&] { grainlab::load_mesh(path); });
}
