// Files written under a temporary name in their own folder and renamed into
// place when complete (rename is atomic within one file system), so a killed
// run leaves no torn file. (core/atomic_file.h does this for io's writers; ct
// sits below io, so it has this small helper of its own.)
#pragma once

#include <filesystem>
#include <string_view>

namespace grainlab::ct {

// A fresh name in `path`'s folder, hidden and unique to this process, with
// `path`'s extension kept (ITK's writers look at it).
std::filesystem::path temporary_sibling(const std::filesystem::path& path);

// Renames a complete temporary file onto `path`; removes it and throws
// RunError naming `path` on failure.
void commit_temporary(const std::filesystem::path& tmp, const std::filesystem::path& path);

}  // namespace grainlab::ct
