// Reads back the .vtp and .pvd files that vtk_writer.h writes: a minimal XML
// reader for that format only (elements, attributes, inline base64 binary
// DataArrays, or raw appended ones, zlib-compressed or not, with a UInt32 or
// UInt64 header). Not a general VTK reader: no ascii data, no base64 appended
// data, no compressed inline data, no triangle strips.
#pragma once

#include "io/vtk_writer.h"

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace grainlab {

// The PolyData of a .vtp file; throws InputError naming the file and what is
// wrong for a missing, malformed or unsupported file.
PolyData read_vtp(const std::filesystem::path& path);

// Parses .vtp text; source_name is used in messages.
PolyData parse_vtp(std::string_view text, const std::string& source_name);

// The entries of a .pvd collection, in file order (InputError on a bad file).
std::vector<PvdEntry> read_pvd(const std::filesystem::path& path);

// Parses .pvd text; source_name is used in messages.
std::vector<PvdEntry> parse_pvd(std::string_view text, const std::string& source_name);

}  // namespace grainlab
