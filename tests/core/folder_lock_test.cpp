// core/folder_lock.h: one holder at a time (a second one is refused naming
// the folder and the holder's pid), the lock of a killed holder is free at
// once (flock: the kernel drops it), and a folder the lock made is removed
// again when nothing but the lock went into it.
#include "core/folder_lock.h"

#include "core/error.h"

#include "temp_folder.h"

#include <gtest/gtest.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <string>

#include <sys/wait.h>
#include <unistd.h>

using namespace grainlab;

namespace {

namespace fs = std::filesystem;

struct LockFolder : core_test::TempFolder {
  LockFolder() : TempFolder("lock") {}
};

std::string refusal(const fs::path& folder) {
  try {
    FolderLock second(folder, "grainlab run");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(locked twice)";
}

TEST(FolderLock, ASecondHolderIsRefusedNamingTheFolderAndTheFirst) {
  LockFolder d;
  const fs::path out = d.path / "run";
  {
    FolderLock first(out, "grainlab run");
    std::ofstream(out / "series.csv") << "t\n";
    const std::string msg = refusal(out);
    EXPECT_NE(msg.find(out.string()), std::string::npos) << msg;
    EXPECT_NE(msg.find("in use by process " + std::to_string(::getpid())), std::string::npos) << msg;
    EXPECT_NE(msg.find("another output folder"), std::string::npos) << msg;
  }
  FolderLock again(out, "grainlab run");  // released with the first
  EXPECT_TRUE(fs::exists(out / "series.csv"));
}

TEST(FolderLock, AKilledHoldersLockIsNotStale) {
  LockFolder d;
  const fs::path out = d.path / "run";
  int ready[2];
  ASSERT_EQ(::pipe(ready), 0);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    FolderLock held(out, "grainlab run");
    std::ofstream(out / "config.toml") << "seed = 1\n";
    const char c = 'x';
    (void)!::write(ready[1], &c, 1);
    ::pause();
    ::_exit(0);
  }
  char c = 0;
  ASSERT_EQ(::read(ready[0], &c, 1), 1);
  EXPECT_NE(refusal(out).find("process " + std::to_string(child)), std::string::npos);
  ::kill(child, SIGKILL);
  ::waitpid(child, nullptr, 0);
  FolderLock mine(out, "grainlab run");  // no stale lock to clear by hand
  ::close(ready[0]);
  ::close(ready[1]);
}

TEST(FolderLock, AFolderWithNothingButTheLockIsRemovedAgain) {
  LockFolder d;
  { FolderLock refused_run(d.path / "new", "grainlab run"); }
  EXPECT_FALSE(fs::exists(d.path / "new"));
  fs::create_directories(d.path / "kept");
  { FolderLock earlier(d.path / "kept", "grainlab run"); }
  EXPECT_TRUE(fs::exists(d.path / "kept"));  // not made by the lock: kept
}

TEST(FolderLock, AFileInTheWayIsRefusedAsInput) {
  LockFolder d;
  std::ofstream(d.path / "file") << "x";
  try {
    FolderLock l(d.path / "file", "grainlab run");
    ADD_FAILURE() << "locked a file";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("output folder"), std::string::npos) << e.what();
  }
}

}  // namespace
