// write_file_atomically: POSIX open/write/fsync/rename, then fsync of the
// folder so the rename itself survives a crash.
#include "core/atomic_file.h"

#include "core/error.h"

#include <fmt/format.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <string>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace grainlab {

void write_file_atomically(const std::filesystem::path& path, std::string_view contents) {
  static std::atomic<unsigned> counter{0};
  const std::filesystem::path folder = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
  const std::filesystem::path tmp =
      folder / fmt::format(".{}.tmp.{}.{}", path.filename().string(), ::getpid(), counter++);

  const auto fail = [&](const char* what, int err, bool remove_tmp) {
    if (remove_tmp) ::unlink(tmp.c_str());
    throw RunError(fmt::format("cannot write '{}': {} failed: {}. Check that the folder exists, is writable "
                               "and the disk is not full.",
                               path.string(), what, std::strerror(err)));
  };

  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
  if (fd < 0) fail("creating a temporary file", errno, false);
  const char* data = contents.data();
  std::size_t left = contents.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, data, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      const int err = errno;
      ::close(fd);
      fail("write", err, true);
    }
    data += n;
    left -= static_cast<std::size_t>(n);
  }
  if (::fsync(fd) != 0) {
    const int err = errno;
    ::close(fd);
    fail("fsync", err, true);
  }
  if (::close(fd) != 0) fail("close", errno, true);
  if (::rename(tmp.c_str(), path.c_str()) != 0) fail("rename", errno, true);

  // Make the rename durable; a failure here leaves a complete file, so it is not an error.
  const int dir = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir >= 0) {
    ::fsync(dir);
    ::close(dir);
  }
}

}  // namespace grainlab
