// The grains of a segmented CT scan (`grainlab ct segment`: a folder with
// one mesh per grain and grains.csv), read at the poses where they were
// scanned, for a specimen rebuilt grain by grain (issue 12 item 4).
#pragma once

#include "geometry/trimesh.h"

#include <filesystem>
#include <string>
#include <vector>

namespace grainlab {

struct ScannedGrains {
  std::vector<TriMesh> meshes;     // in the scan's world coordinates (m), as segmented
  std::vector<std::string> names;  // the mesh files' stems
  int border_dropped = 0;          // grains touching the image border left out
};

// Reads DIR/grains.csv (columns id, file, ..., border; see docs/ct.md) and
// every mesh it names (load_mesh: checked and repaired). Grains with
// border = 1 are cut by the image's faces: dropped unless keep_border.
// Throws InputError naming the file, the line and the fix for a missing
// folder, file or column, or a bad value, and for a grains.csv that is no
// regular file (a device, a FIFO) or holds more than 256 MiB (checked before
// it is read).
ScannedGrains read_scanned_grains(const std::filesystem::path& dir, bool keep_border);

}  // namespace grainlab
