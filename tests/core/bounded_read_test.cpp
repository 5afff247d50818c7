// core/bounded_read.h: a file is read whole only when it is a regular file
// within the reader's limit; a device, a pipe, a folder or an oversized file
// is refused naming the path, the figure and the limit, before allocating.
#include "core/bounded_read.h"

#include "core/error.h"

#include "temp_folder.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <sys/stat.h>
#include <unistd.h>

using namespace grainlab;

namespace {

namespace fs = std::filesystem;

struct ReadFolder : core_test::TempFolder {
  ReadFolder() : TempFolder("bounded") {}
};

std::string refusal(const fs::path& p, std::uintmax_t limit) {
  try {
    read_bounded_file(p, limit, "config file");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(read)";
}

TEST(BoundedRead, ReadsARegularFileWhole) {
  ReadFolder d;
  std::ofstream(d.path / "a.toml", std::ios::binary) << std::string("x = 1\n\0y", 9);
  EXPECT_EQ(read_bounded_file(d.path / "a.toml", 9, "config file"), std::string("x = 1\n\0y", 9));
  EXPECT_EQ(bounded_file_size(d.path / "a.toml", 100, "config file"), 9u);
}

TEST(BoundedRead, RefusesDevicesPipesAndFolders) {
  ReadFolder d;
  std::string msg = refusal("/dev/zero", 1 << 20);  // grew to 24 GB before
  EXPECT_NE(msg.find("'/dev/zero' is a character device, not a regular file"), std::string::npos) << msg;
  ASSERT_EQ(::mkfifo((d.path / "fifo").c_str(), 0600), 0);
  msg = refusal(d.path / "fifo", 1 << 20);  // opened without blocking on a writer
  EXPECT_NE(msg.find("pipe"), std::string::npos) << msg;
  msg = refusal(d.path, 1 << 20);
  EXPECT_NE(msg.find("is a folder"), std::string::npos) << msg;
  msg = refusal(d.path / "missing.toml", 1 << 20);
  EXPECT_NE(msg.find("cannot open config file"), std::string::npos) << msg;
}

TEST(BoundedRead, RefusesAFileOverTheLimitWithTheFigureAndTheLimit) {
  ReadFolder d;
  std::ofstream(d.path / "big.toml") << std::string(5000, 'a');
  const std::string msg = refusal(d.path / "big.toml", 4096);
  EXPECT_NE(msg.find("big.toml"), std::string::npos) << msg;
  EXPECT_NE(msg.find("5000 bytes"), std::string::npos) << msg;
  EXPECT_NE(msg.find("4096 bytes"), std::string::npos) << msg;
}

TEST(BoundedRead, ExcerptKeepsShortTextAndCutsLongText) {
  EXPECT_EQ(excerpt("short"), "short");
  const std::string cut = excerpt(std::string(10'000'000, 'a'), 20);
  EXPECT_EQ(cut, std::string(20, 'a') + "... (10000000 characters)");
}

}  // namespace
