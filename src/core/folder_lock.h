// One process at a time in an output folder: an advisory lock (flock) on the
// file FOLDER/.grainlab.lock, held while the process lives. The kernel drops
// it when the process ends however it ends (kill -9 included), so a lock is
// never stale; the file itself stays and says who held it last (pid, host).
#pragma once

#include <filesystem>
#include <string>

namespace grainlab {

class FolderLock {
 public:
  // Creates `folder` if missing and takes its lock (released, and a folder
  // this made removed again if nothing but the lock file is in it, when this
  // object ends). Throws InputError naming
  // the folder and the holder's pid and host when another process holds it,
  // and `what_runs` (e.g. "grainlab run") in the fix.
  FolderLock(const std::filesystem::path& folder, const std::string& what_runs);
  ~FolderLock();
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;

  // The lock file's name inside the folder.
  static constexpr const char* kFileName = ".grainlab.lock";

 private:
  int fd_ = -1;
  std::filesystem::path folder_;
  bool created_ = false;  // the folder did not exist: removed again when nothing but the lock was written
};

}  // namespace grainlab
