// Every reader of io bounds what it allocates by the input's real size: a
// device (/dev/zero grew `grainlab run` to 24 GB), a pipe or an oversized file
// is refused before it is read, and a hostile value (a 10 MB string, a long
// key) is quoted only by its start, so that messages stay short.
#include "core/error.h"
#include "grains/scanned_grains.h"
#include "grains/sh_grain.h"
#include "io/checkpoint.h"
#include "io/config.h"
#include "io/json.h"
#include "io/pvd_reader.h"
#include "io/sh_spectrum_file.h"
#include "io/table.h"
#include "io_test_helpers.h"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

namespace grainlab {
namespace {

TEST(OversizedInput, EveryReaderRefusesADeviceBeforeReadingIt) {
  const std::filesystem::path zero = "/dev/zero";
  for (const auto& read : std::vector<std::function<void()>>{
           [&] { load_config(zero); }, [&] { load_checkpoint(zero); }, [&] { read_pvd(zero); },
           [&] { read_json_file(zero); }, [&] { read_csv(zero); }, [&] { read_sh_file(zero); },
           [&] { read_sh_spectrum(zero); }}) {
    const std::string msg = test::error_of<InputError>(read);
    EXPECT_NE(msg.find("'/dev/zero' is a character device, not a regular file"), std::string::npos) << msg;
  }
}

// grains.scan's grains.csv was read line by line without a bound.
TEST(OversizedInput, AScanFoldersGrainTableThatIsADeviceIsRefused) {
  test::IoTempDir dir;
  std::filesystem::create_symlink("/dev/zero", dir.path / "grains.csv");
  const std::string msg = test::error_of<InputError>([&] { read_scanned_grains(dir.path, false); });
  EXPECT_NE(msg.find("grain table"), std::string::npos) << msg;
  EXPECT_NE(msg.find("is a character device, not a regular file"), std::string::npos) << msg;
}

TEST(OversizedInput, AScanFoldersMeshNameTooLongOrWithAControlCharacterIsRefused) {
  // std::filesystem::exists threw on a name over the system's 255 bytes (an exception escaping as an internal error).
  test::IoTempDir dir;
  const std::string head = "id,file,x_m,y_m,z_m,qw,qx,qy,qz,volume_m3,equivalent_diameter_m,border\n1,";
  const std::string tail = ",0,0,0,1,0,0,0,1e-12,1e-4,0\n";
  std::ofstream(dir.path / "grains.csv") << head << std::string(300, 'g') << ".stl" << tail;
  std::string msg = test::error_of<InputError>([&] { read_scanned_grains(dir.path, false); });
  EXPECT_NE(msg.find("grains.csv:2: the mesh"), std::string::npos) << msg;
  EXPECT_NE(msg.find("does not exist (File name too long)"), std::string::npos) << msg;
  std::ofstream(dir.path / "grains.csv") << head << "grain\x01.stl" << tail;
  msg = test::error_of<InputError>([&] { read_scanned_grains(dir.path, false); });
  EXPECT_NE(msg.find("grains.csv:2: file = 'grain\x01.stl' holds a control character"), std::string::npos) << msg;
}

TEST(OversizedInput, AConfigOverItsLimitIsRefusedWithTheFigure) {
  test::IoTempDir dir;
  const auto file = dir.path / "big.toml";
  std::ofstream(file) << "[grains]\npreset = \"" << std::string(5 << 20, 'a') << "\"\n";
  const std::string msg = test::error_of<InputError>([&] { load_config(file); });
  EXPECT_NE(msg.find("big.toml"), std::string::npos) << msg;
  EXPECT_NE(msg.find("5242" ), std::string::npos) << msg;  // its 5242900-odd bytes
  EXPECT_NE(msg.find("4194304 bytes (4 MiB)"), std::string::npos) << msg;
  EXPECT_LT(msg.size(), 400u);
}

TEST(OversizedInput, ALongStringOrKeyIsQuotedByItsStartOnly) {
  // Within the file limit, but no key or value of grainlab is that long.
  const std::string value = std::string(100000, 'a');
  std::string msg = test::error_of<InputError>(
      [&] { parse_config("[grains]\npreset = \"" + value + "\"\n", "long.toml"); });
  EXPECT_NE(msg.find("long.toml (line 2)"), std::string::npos) << msg;
  EXPECT_NE(msg.find("a string of 100000 characters"), std::string::npos) << msg;
  EXPECT_LT(msg.size(), 400u) << "echoes the value whole";
  msg = test::error_of<InputError>(
      [&] { parse_config("[output]\nfolder = \"" + std::string(5000, 'f') + "\"\n", "path.toml"); });
  EXPECT_NE(msg.find("4096"), std::string::npos) << msg;  // a path's system limit
  msg = test::error_of<InputError>([&] { parse_config("[grains]\n" + std::string(5000, 'k') + " = 1\n", "key.toml"); });
  EXPECT_NE(msg.find("a key of 5000 characters"), std::string::npos) << msg;
  EXPECT_LT(msg.size(), 400u);
  // A string of ordinary length is still echoed whole in its own message.
  msg = test::error_of<InputError>([&] { parse_config("[grains]\npreset = \"roundd\"\n", "typo.toml"); });
  EXPECT_NE(msg.find("\"roundd\""), std::string::npos) << msg;
}

TEST(OversizedInput, ACheckpointCountBeyondItsBytesIsRefused) {
  // The header of a real checkpoint, then a body count no file this small can hold.
  test::IoTempDir dir;
  const auto file = dir.path / "specimen.bin";
  save_checkpoint(file, State{}, {}, 1);
  std::string bytes;
  {
    std::ifstream in(file, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  bytes.resize(bytes.size() / 2);
  std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes;
  const std::string msg = test::error_of<InputError>([&] { load_checkpoint(file); });
  EXPECT_NE(msg.find("specimen.bin"), std::string::npos) << msg;
}

}  // namespace
}  // namespace grainlab
