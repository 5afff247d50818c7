// write_file_atomically: POSIX open/write/fsync/rename, then fsync of the
// folder so the rename itself survives a crash. A write that fails with
// EFBIG (the file-size limit, with SIGXFSZ not fatal) or ENOSPC unlinks the
// temporary, so nothing half-written is ever left under a final name.
#include "core/atomic_file.h"

#include "core/bounded_read.h"
#include "core/error.h"

#include <fmt/format.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <string>
#include <system_error>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace grainlab {
// What to do about a failed write, by the system's error.
std::string fix_for_write_error(int err) {
  switch (err) {
    case ENOENT: return "create the folder first, or give a path in an existing folder";
    case ENOTDIR: return "a part of the path is a file, not a folder; give another path";
    case ENAMETOOLONG: return "a name in the path is longer than the file system allows (255 bytes a name); "
                              "give a shorter path";
    case EISDIR: return "the path is a folder; give a file path";
    case EACCES:
    case EPERM: return "the folder is not writable by this user; choose a writable folder or fix its permissions";
    case EROFS: return "the file system is read-only; choose a folder on a writable disk";
    case ENOSPC:
    case EDQUOT: return "the disk (or your quota) is full; free space and run the command again";
    case EFBIG: return "the file is larger than this process may write (the file-size limit, `ulimit -f`); raise "
                       "the limit and run the command again";
    default: return "check that the folder exists and is writable and that the disk is not full";
  }
}

bool is_path_error(int err) { return err == ENOENT || err == ENOTDIR || err == ENAMETOOLONG || err == EISDIR; }

namespace {

std::string failure(const std::filesystem::path& path, const char* what, int err) {
  return fmt::format("cannot write '{}': {} failed: {}; {}. Nothing was written under that name",
                     excerpt(path.string(), 300), what, std::strerror(err), fix_for_write_error(err));
}

[[noreturn]] void fail(const std::filesystem::path& path, const char* what, int err) {
  throw WriteError(failure(path, what, err));
}

// A target that exists and is no regular file, which the rename would replace.
void refuse_non_regular(const std::filesystem::path& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode))
    input_error("cannot write '{}': it is {}, not a regular file, and grainlab writes a file through a temporary "
                "renamed over the target, which would replace it; give the path of a file",
                excerpt(path.string(), 300), file_kind(path));
}

bool is_temporary_name(const std::string& name) {
  // ".NAME.tmp.PID.N": a leading dot, ".tmp." and then digits, a dot, digits.
  const std::size_t at = name.rfind(".tmp.");
  if (name.size() < 2 || name[0] != '.' || at == std::string::npos || at == 0) return false;
  const std::string tail = name.substr(at + 5);
  const std::size_t dot = tail.find('.');
  if (dot == std::string::npos || dot == 0 || dot + 1 == tail.size()) return false;
  return tail.find_first_not_of("0123456789.") == std::string::npos && tail.find('.', dot + 1) == std::string::npos;
}

}  // namespace

void check_file_target(const std::filesystem::path& path) {
  refuse_non_regular(path);
  const std::filesystem::path folder = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
  struct stat st {};
  const int err = ::stat(folder.c_str(), &st) != 0 ? errno : S_ISDIR(st.st_mode) ? 0 : ENOTDIR;
  if (err) throw InputError(failure(path, "finding its folder", err));
}

void write_file_atomically(const std::filesystem::path& path, std::string_view contents) {
  static std::atomic<unsigned> counter{0};
  refuse_non_regular(path);
  const std::filesystem::path folder = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
  const std::filesystem::path tmp =
      folder / fmt::format(".{}.tmp.{}.{}", path.filename().string(), ::getpid(), counter++);

  const auto fail_removing = [&](const char* what, int err) {
    ::unlink(tmp.c_str());
    fail(path, what, err);
  };
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
  if (fd < 0) fail(path, "creating a temporary file", errno);
  const char* data = contents.data();
  std::size_t left = contents.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, data, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      const int err = errno;
      ::close(fd);
      fail_removing("write", err);
    }
    data += n;
    left -= static_cast<std::size_t>(n);
  }
  if (::fsync(fd) != 0) {
    const int err = errno;
    ::close(fd);
    fail_removing("fsync", err);
  }
  if (::close(fd) != 0) fail_removing("close", errno);
  if (::rename(tmp.c_str(), path.c_str()) != 0) fail_removing("rename", errno);

  // Make the rename durable; a failure here leaves a complete file, so it is not an error.
  const int dir = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir >= 0) {
    ::fsync(dir);
    ::close(dir);
  }
}

int remove_stale_temporaries(const std::filesystem::path& folder) {
  std::error_code ec;
  int removed = 0;
  for (auto it = std::filesystem::recursive_directory_iterator(folder, ec);
       !ec && it != std::filesystem::recursive_directory_iterator(); it.increment(ec)) {
    if (it->is_regular_file(ec) && is_temporary_name(it->path().filename().string()))
      removed += std::filesystem::remove(it->path(), ec) ? 1 : 0;
  }
  return removed;
}

}  // namespace grainlab
