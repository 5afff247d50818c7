// Reads back the .pvd collections that vtk_writer.h writes (ParaView's list
// of a series' files with their times): grainlab's own format only, through
// the tag scanner of xml_scanner.h. A resumed run reads its collections back
// to go on appending to them.
#pragma once

#include "io/vtk_writer.h"

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace grainlab {

// The entries of a .pvd collection, in file order (InputError on a bad file).
std::vector<PvdEntry> read_pvd(const std::filesystem::path& path);

// Parses .pvd text; source_name is used in messages.
std::vector<PvdEntry> parse_pvd(std::string_view text, const std::string& source_name);

}  // namespace grainlab
