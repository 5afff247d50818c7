// Fuzz harness: grains.csv of a segmented scan (grains/scanned_grains.h,
// the folder `grainlab ct segment` writes and `grains.scan` names). The
// table is fuzzed; beside it lie grain_0001.stl and grain_0002.stl (a small
// tetrahedron), so that rows naming them reach the rest of the reader.
// See harness_input.h.
#include "fuzz/harness_input.h"
#include "grains/scanned_grains.h"

#include <string_view>

namespace {

// A tetrahedron of 0.2 mm edges, ASCII STL, in metres.
constexpr std::string_view kTetra =
    "solid t\n"
    "facet normal 0 0 -1\nouter loop\nvertex 0 0 0\nvertex 0 2e-4 0\nvertex 2e-4 0 0\nendloop\nendfacet\n"
    "facet normal 0 -1 0\nouter loop\nvertex 0 0 0\nvertex 2e-4 0 0\nvertex 0 0 2e-4\nendloop\nendfacet\n"
    "facet normal -1 0 0\nouter loop\nvertex 0 0 0\nvertex 0 0 2e-4\nvertex 0 2e-4 0\nendloop\nendfacet\n"
    "facet normal 1 1 1\nouter loop\nvertex 2e-4 0 0\nvertex 0 2e-4 0\nvertex 0 0 2e-4\nendloop\nendfacet\n"
    "endsolid t\n";

void write_meshes() {
  static const bool written = [] {
    const std::span<const std::uint8_t> bytes(reinterpret_cast<const std::uint8_t*>(kTetra.data()), kTetra.size());
    grainlab::fuzz::input_file(bytes, "grain_0001.stl");
    grainlab::fuzz::input_file(bytes, "grain_0002.stl");
    return true;
  }();
  (void)written;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  write_meshes();
  const auto csv = grainlab::fuzz::input_file({data, size}, "grains.csv");
  return grainlab::fuzz::refused_or_read([&] { grainlab::read_scanned_grains(csv.parent_path(), true); });
}
