// Atomic writes: the file appears whole, replaces an old one, and a failed
// write leaves nothing behind.
#include "core/atomic_file.h"

#include "core/error.h"
#include "io_test_helpers.h"
#include "file_text.h"

#include <gtest/gtest.h>

#include <csignal>
#include <fstream>
#include <sstream>

#include <sys/resource.h>
#include <sys/stat.h>

namespace grainlab {
namespace {

std::size_t files_in(const std::filesystem::path& dir) {
  std::size_t n = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir)) ++n;
  return n;
}

TEST(AtomicFile, WritesTheWholeFileAndReplacesAnOldOne) {
  test::IoTempDir dir;
  const auto file = dir.path / "series.csv";
  std::string big(1 << 20, 'x');
  big[12345] = '\0';  // binary-safe
  write_file_atomically(file, big);
  EXPECT_EQ(test::file_text(file), big);
  write_file_atomically(file, "short\n");
  EXPECT_EQ(test::file_text(file), "short\n");
  EXPECT_EQ(files_in(dir.path), 1u);  // no temporary left over
}

TEST(AtomicFile, MissingFolderThrowsAndLeavesNothing) {
  test::IoTempDir dir;
  const auto file = dir.path / "missing" / "run.json";
  const std::string msg = test::error_of<RunError>([&] { write_file_atomically(file, "{}"); });
  EXPECT_NE(msg.find(file.string()), std::string::npos) << msg;
  EXPECT_EQ(files_in(dir.path), 0u);
}

TEST(AtomicFile, FailedWriteRemovesTheTemporaryAndKeepsTheOldFile) {
  // Make the write itself fail half way: a file size limit (EFBIG instead of
  // SIGXFSZ). Works as root too, unlike a read-only folder.
  test::IoTempDir dir;
  const auto file = dir.path / "checkpoint.bin";
  write_file_atomically(file, "old");
  rlimit old_limit{};
  ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &old_limit), 0);
  rlimit small = old_limit;
  small.rlim_cur = 4096;
  const auto old_handler = std::signal(SIGXFSZ, SIG_IGN);
  ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &small), 0);
  std::string msg;
  try {
    write_file_atomically(file, std::string(100000, 'y'));
  } catch (const RunError& e) {
    msg = e.what();
  }
  ::setrlimit(RLIMIT_FSIZE, &old_limit);
  std::signal(SIGXFSZ, old_handler);
  EXPECT_NE(msg.find(file.string()), std::string::npos) << msg;
  EXPECT_NE(msg.find("File too large"), std::string::npos) << msg;
  EXPECT_NE(msg.find("ulimit -f"), std::string::npos) << msg;
  EXPECT_EQ(test::file_text(file), "old");
  EXPECT_EQ(files_in(dir.path), 1u);
}

// `grains index --json /dev/full` once printed "wrote /dev/full": as root the
// rename replaced the device with a regular file. A target that exists and is
// no regular file is refused as bad input and left as it is.
TEST(AtomicFile, ATargetThatIsNoRegularFileIsRefusedAndKept) {
  test::IoTempDir dir;
  const auto fifo = dir.path / "pipe.json";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::string msg = test::error_of<InputError>([&] { write_file_atomically(fifo, "{}"); });
  EXPECT_NE(msg.find("pipe.json"), std::string::npos) << msg;
  EXPECT_NE(msg.find("not a regular file"), std::string::npos) << msg;
  EXPECT_TRUE(std::filesystem::is_fifo(fifo));
  msg = test::error_of<InputError>([&] { write_file_atomically(dir.path, "{}"); });
  EXPECT_NE(msg.find("a folder"), std::string::npos) << msg;
  EXPECT_EQ(files_in(dir.path), 1u);
  // The check a command makes before it works: the same, and a missing folder is bad input too.
  EXPECT_THROW(check_file_target(fifo), InputError);
  msg = test::error_of<InputError>([&] { check_file_target(dir.path / "missing" / "index.json"); });
  EXPECT_NE(msg.find("create the folder first"), std::string::npos) << msg;
  EXPECT_NO_THROW(check_file_target(dir.path / "index.json"));
}

TEST(AtomicFile, StaleTemporariesOfAKilledRunAreRemovedAndNothingElse) {
  test::IoTempDir dir;
  std::filesystem::create_directories(dir.path / "paraview");
  for (const char* name : {".series.csv.tmp.4242.0", "paraview/.grains_0003.vtp.tmp.17.12", "series.csv",
                           ".grainlab.lock", "notes.tmp.txt", ".x.tmp.12", ".tmp.1.2"})
    std::ofstream(dir.path / name) << "x";
  EXPECT_EQ(remove_stale_temporaries(dir.path), 2);
  EXPECT_FALSE(std::filesystem::exists(dir.path / ".series.csv.tmp.4242.0"));
  EXPECT_FALSE(std::filesystem::exists(dir.path / "paraview/.grains_0003.vtp.tmp.17.12"));
  for (const char* kept : {"series.csv", ".grainlab.lock", "notes.tmp.txt", ".x.tmp.12", ".tmp.1.2"})
    EXPECT_TRUE(std::filesystem::exists(dir.path / kept)) << kept;
}

}  // namespace
}  // namespace grainlab
