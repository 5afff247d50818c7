// FolderLock: open (create) the lock file, flock(LOCK_EX | LOCK_NB), then
// check that the name still points at the file locked (another process may
// have replaced it between the open and the lock), and write "pid host".
#include "core/folder_lock.h"

#include "core/error.h"

#include <cerrno>
#include <cstring>
#include <string>
#include <system_error>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

namespace grainlab {
namespace {

std::string host_name() {
  char buf[256] = {};
  if (::gethostname(buf, sizeof(buf) - 1) != 0) return "an unknown host";
  return buf;
}

// "pid 123 on host" from the lock file's text, or a plain word when it says nothing readable.
std::string holder(int fd) {
  char buf[300] = {};
  const ssize_t n = ::pread(fd, buf, sizeof(buf) - 1, 0);
  std::string text = n > 0 ? std::string(buf, static_cast<std::size_t>(n)) : std::string();
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  const std::size_t space = text.find(' ');
  if (text.empty() || space == std::string::npos) return "another process";
  return fmt::format("process {} on {}", excerpt(text.substr(0, space), 20), excerpt(text.substr(space + 1), 100));
}

}  // namespace

FolderLock::FolderLock(const std::filesystem::path& folder, const std::string& what_runs) {
  const std::filesystem::path file = folder / kFileName;
  for (int attempt = 0; attempt < 100; ++attempt) {
    std::error_code ec;
    created_ = std::filesystem::create_directories(folder, ec) || created_;
    if (ec || !std::filesystem::is_directory(folder))
      input_error("cannot use '{}' as the output folder: {}; give a folder path whose parent folders exist, are "
                  "writable and are not files",
                  excerpt(folder.string(), 300), ec ? ec.message() : std::string("a file of that name is in the way"));
    const int fd = ::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd < 0)
      throw WriteError(fmt::format("cannot create the lock file '{}': {}; choose a writable output folder",
                                   excerpt(file.string(), 300), std::strerror(errno)));
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
      const int err = errno;
      const std::string who = holder(fd);
      ::close(fd);
      if (err == EWOULDBLOCK)
        input_error("output folder '{}' is in use by {} (its lock, {}). Two runs in one folder would mix their "
                    "files: wait for that {} to end or stop it, or give this one another output folder",
                    excerpt(folder.string(), 300), who, kFileName, what_runs);
      throw WriteError(fmt::format("cannot lock '{}': {}; the file system may not support locks (flock): use a "
                                   "local output folder",
                                   excerpt(file.string(), 300), std::strerror(err)));
    }
    struct stat locked {}, named {};
    if (::fstat(fd, &locked) == 0 && ::stat(file.c_str(), &named) == 0 && locked.st_ino == named.st_ino &&
        locked.st_dev == named.st_dev) {
      const std::string me = fmt::format("{} {}\n", ::getpid(), host_name());
      if (::ftruncate(fd, 0) == 0 && ::pwrite(fd, me.data(), me.size(), 0) < 0) {
        // The lock holds without the note; the message of a second run then says "another process".
      }
      fd_ = fd;
      folder_ = folder;
      return;
    }
    ::close(fd);  // the file was replaced after we opened it: lock the new one
  }
  throw WriteError(fmt::format("cannot lock '{}': it keeps being replaced", excerpt(file.string(), 300)));
}

FolderLock::~FolderLock() {
  if (fd_ < 0) return;
  // A run refused before it wrote anything leaves no folder behind (a waiting
  // process finds the lock file gone and locks a new one).
  std::error_code ec;
  if (created_) {
    bool only_lock = true;
    for (const auto& e : std::filesystem::directory_iterator(folder_, ec))
      only_lock = only_lock && e.path().filename() == kFileName;
    if (!ec && only_lock) {
      std::filesystem::remove(folder_ / kFileName, ec);
      ::close(fd_);
      std::filesystem::remove(folder_, ec);
      return;
    }
  }
  ::close(fd_);
}

}  // namespace grainlab
