#include "fuzz/harness_input.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <string>
#include <unistd.h>

namespace grainlab::fuzz {

namespace {

// The folder, made at the first call and removed with what it holds at exit.
struct OwnFolder {
  std::filesystem::path path;
  OwnFolder() {
    const std::filesystem::path shm = "/dev/shm";
    const std::filesystem::path base = std::filesystem::is_directory(shm) ? shm : std::filesystem::temp_directory_path();
    path = base / ("grainlab-fuzz-" + std::to_string(::getpid()));
    std::filesystem::create_directories(path);
  }
  ~OwnFolder() {
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
  }
};

const std::filesystem::path& own_folder() {
  static const OwnFolder folder;
  return folder.path;
}

}  // namespace

std::filesystem::path input_file(std::span<const std::uint8_t> bytes, std::string_view name) {
  const std::filesystem::path path = own_folder() / std::string(name);
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  out.close();
  if (!out) throw std::runtime_error("fuzz harness: cannot write its input file " + path.string());
  return path;
}

void report_refusal(const InputError& e) {
  static const bool verbose = std::getenv("GRAINLAB_FUZZ_VERBOSE") != nullptr;
  if (verbose) std::fprintf(stderr, "refused: %s\n", e.what());
}

}  // namespace grainlab::fuzz
