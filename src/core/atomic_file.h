// Whole-file writes that never leave a torn file: the contents go to a
// temporary name in the same folder, are flushed to disk, and the temporary
// is renamed over the target (rename is atomic within one file system).
#pragma once

#include <filesystem>
#include <string_view>

namespace grainlab {

// Writes `contents` to `path` atomically. On failure removes the temporary
// file and throws RunError naming the path and the system's reason.
void write_file_atomically(const std::filesystem::path& path, std::string_view contents);

}  // namespace grainlab
