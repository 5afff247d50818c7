// Shared helpers for the geometry tests: temporary directories, error text
// and a concave test mesh.
#pragma once

#include "core/error.h"
#include "geometry/primitives.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <string>

namespace grainlab::test {

// A fresh directory under the system temp dir, removed with everything in it.
struct TempDir {
  std::filesystem::path path;
  TempDir() {
    static std::atomic<int> counter{0};
    path = std::filesystem::temp_directory_path() /
           ("grainlab-geometry-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    std::filesystem::remove_all(path);
    std::filesystem::create_directories(path);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  // A path inside the directory.
  std::filesystem::path operator/(const std::string& name) const { return path / name; }
};

// The message of the InputError that f throws, or "(no InputError)".
template <typename F>
std::string input_error_of(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no InputError)";
}

// A U in the xy plane, 6 wide and 3 high, bars 1 thick, 2 deep along z
// (concave: several convex pieces).
inline TriMesh u_prism() {
  return prism_mesh({{-3, 0}, {3, 0}, {3, 3}, {2, 3}, {2, 1}, {-2, 1}, {-2, 3}, {-3, 3}}, 1.0);
}

}  // namespace grainlab::test

// Passes if `text` contains `part`; prints the whole text otherwise.
#define EXPECT_CONTAINS(text, part) \
  EXPECT_NE(std::string(text).find(part), std::string::npos) << "message: " << (text)
