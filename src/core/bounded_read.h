// Reading a user's file whole, with its size bounded before anything is
// allocated: a device (/dev/zero), a FIFO or a folder is refused, and so is a
// file larger than what its reader accepts, each with the figure and the limit.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace grainlab {

inline constexpr std::uintmax_t kMiB = 1024 * 1024;

// The size of `path` in bytes. Throws InputError (naming `what`, e.g. "config
// file", and the path) when it cannot be opened, is not a regular file, or
// holds more than `limit` bytes.
std::uintmax_t bounded_file_size(const std::filesystem::path& path, std::uintmax_t limit, std::string_view what);

// The bytes of `path`, after the checks of bounded_file_size.
std::string read_bounded_file(const std::filesystem::path& path, std::uintmax_t limit, std::string_view what);

// "a folder", "a character device", ...: what a non-regular file is, for messages.
std::string file_kind(const std::filesystem::path& path);

}  // namespace grainlab
