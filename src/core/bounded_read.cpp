// read_bounded_file: open, fstat the open descriptor (so the checked file is
// the one read), then read at most its size.
#include "core/bounded_read.h"

#include "core/error.h"

#include <cerrno>
#include <cstring>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace grainlab {
namespace {

std::string kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "a folder";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISFIFO(mode)) return "a pipe (FIFO)";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

// An open descriptor of `path` and its size, checked; closes it on refusal.
int open_bounded(const std::filesystem::path& path, std::uintmax_t limit, std::string_view what,
                 std::uintmax_t& size) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) {
    const int err = errno;
    input_error("cannot open {} '{}': {}. Check the path and its permissions", what, excerpt(path.string(), 200),
                std::strerror(err));
  }
  struct stat st {};
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    const std::string kind = kind_of(st.st_mode);
    ::close(fd);
    input_error("{} '{}' is {}, not a regular file; give the path of a file", what, excerpt(path.string(), 200), kind);
  }
  size = static_cast<std::uintmax_t>(st.st_size);
  if (size > limit) {
    ::close(fd);
    input_error("{} '{}' holds {} bytes, more than the {} bytes ({} MiB) grainlab reads for a {}; it is not such a "
                "file, or it is damaged",
                what, excerpt(path.string(), 200), size, limit, limit / kMiB, what);
  }
  return fd;
}

}  // namespace

std::string file_kind(const std::filesystem::path& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return "missing";
  return S_ISREG(st.st_mode) ? "a regular file" : kind_of(st.st_mode);
}

std::uintmax_t bounded_file_size(const std::filesystem::path& path, std::uintmax_t limit, std::string_view what) {
  std::uintmax_t size = 0;
  ::close(open_bounded(path, limit, what, size));
  return size;
}

std::string read_bounded_file(const std::filesystem::path& path, std::uintmax_t limit, std::string_view what) {
  std::uintmax_t size = 0;
  const int fd = open_bounded(path, limit, what, size);
  std::string bytes(static_cast<std::size_t>(size), '\0');
  std::size_t got = 0;
  while (got < bytes.size()) {
    const ssize_t n = ::read(fd, bytes.data() + got, bytes.size() - got);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      const int err = errno;
      ::close(fd);
      input_error("{} '{}': read error: {}", what, excerpt(path.string(), 200), std::strerror(err));
    }
    if (n == 0) break;  // shrank since fstat: keep what is there
    got += static_cast<std::size_t>(n);
  }
  ::close(fd);
  bytes.resize(got);
  return bytes;
}

}  // namespace grainlab
