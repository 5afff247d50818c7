#include "ct/temp_file.h"

#include "core/error.h"

#include <fmt/format.h>
#include <unistd.h>

#include <atomic>
#include <fstream>

namespace grainlab::ct {

namespace fs = std::filesystem;

fs::path temporary_sibling(const fs::path& path) {
  static std::atomic<unsigned> counter{0};
  const fs::path folder = path.has_parent_path() ? path.parent_path() : fs::path(".");
  return folder / fmt::format(".{}.tmp.{}.{}{}", path.stem().string(), ::getpid(), counter++,
                              path.extension().string());
}

void commit_temporary(const fs::path& tmp, const fs::path& path) {
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) {
    fs::remove(tmp, ec);
    throw RunError(fmt::format("cannot write '{}': rename of the finished temporary file failed: {}. Check that "
                               "the folder is writable.",
                               path.string(), ec.message()));
  }
}

}  // namespace grainlab::ct
