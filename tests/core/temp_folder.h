// A fresh folder under the system temp dir for one core test, removed with everything in it.
#pragma once

#include <filesystem>
#include <string>

#include <unistd.h>

namespace grainlab::core_test {

struct TempFolder {
  std::filesystem::path path;
  explicit TempFolder(const std::string& name)
      : path(std::filesystem::temp_directory_path() / ("grainlab-" + name + "-" + std::to_string(::getpid()))) {
    std::filesystem::remove_all(path);
    std::filesystem::create_directories(path);
  }
  ~TempFolder() {
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
  }
};

}  // namespace grainlab::core_test
