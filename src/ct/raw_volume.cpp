#include "ct/raw_volume.h"

#include "core/error.h"
#include "core/atomic_file.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <string>

namespace grainlab::ct {

namespace fs = std::filesystem;

static_assert(std::endian::native == std::endian::little, "raw volumes are read as little endian");

template <typename T>
T to_voxel(float v) {
  if constexpr (std::is_floating_point_v<T>) {
    return static_cast<T>(v);
  } else {
    const double lo = std::numeric_limits<T>::min(), hi = std::numeric_limits<T>::max();
    return static_cast<T>(std::clamp(std::round(static_cast<double>(v)), lo, hi));
  }
}
template std::uint8_t to_voxel<std::uint8_t>(float);
template std::uint16_t to_voxel<std::uint16_t>(float);
template float to_voxel<float>(float);

void check_raw_file(const fs::path& path, const RawLayout& layout) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) input_error("raw image '{}' does not exist or is not a file", path.string());
  const auto bytes = fs::file_size(path, ec);
  if (ec) input_error("cannot read the size of raw image '{}': {}", path.string(), ec.message());
  const std::uint64_t need = static_cast<std::uint64_t>(layout.size[0]) * layout.size[1] * layout.size[2] *
                             voxel_bytes(layout.type);
  const std::string dims = fmt::format("{} x {} x {} voxels of {}", layout.size[0], layout.size[1],
                                       layout.size[2], voxel_type_name(layout.type));
  if (bytes == 0) input_error("raw image '{}' is empty (0 bytes); --size and --type say {} ({} bytes)",
                              path.string(), dims, need);
  if (bytes < need) {
    input_error("raw image '{}' is truncated: {} bytes, but --size and --type say {}, which need {} bytes; check "
                "--size and --type, or copy the file again",
                path.string(), bytes, dims, need);
  }
  if (bytes > need) {
    input_error("raw image '{}' has {} bytes, more than the {} bytes of {} (--size and --type); check them: a raw "
                "file must hold the voxels and nothing else (a file with a header is read by its own format, or by "
                "a .mhd header naming it)",
                path.string(), bytes, need, dims);
  }
}

namespace {

template <typename T>
void convert(const std::vector<char>& bytes, std::vector<float>& out) {
  const std::size_t n = bytes.size() / sizeof(T);
  out.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    T v;
    std::memcpy(&v, bytes.data() + i * sizeof(T), sizeof(T));
    out[i] = static_cast<float>(v);
  }
}

template <typename T>
std::string pack(const GreyVolume& volume) {
  std::string out(volume.values.size() * sizeof(T), '\0');
  for (std::size_t i = 0; i < volume.values.size(); ++i) {
    const T v = to_voxel<T>(volume.values[i]);
    std::memcpy(out.data() + i * sizeof(T), &v, sizeof(T));
  }
  return out;
}

}  // namespace

void read_raw_slice(const fs::path& path, const RawLayout& layout, std::int64_t z, std::vector<float>& values) {
  std::ifstream in(path, std::ios::binary);
  const std::size_t n = static_cast<std::size_t>(layout.size[0] * layout.size[1]);
  std::vector<char> bytes(n * voxel_bytes(layout.type));
  in.seekg(static_cast<std::streamoff>(z) * static_cast<std::streamoff>(bytes.size()));
  if (!in.read(bytes.data(), static_cast<std::streamsize>(bytes.size()))) {
    input_error("cannot read slice {} of raw image '{}' ({} bytes at offset {}): was it changed while read?", z,
                path.string(), bytes.size(), z * static_cast<std::int64_t>(bytes.size()));
  }
  switch (layout.type) {
    case VoxelType::UInt8: convert<std::uint8_t>(bytes, values); break;
    case VoxelType::UInt16: convert<std::uint16_t>(bytes, values); break;
    case VoxelType::Float32: convert<float>(bytes, values); break;
  }
}

void write_raw_volume(const GreyVolume& volume, const fs::path& path, VoxelType type) {
  switch (type) {
    case VoxelType::UInt8: write_file_atomically(path, pack<std::uint8_t>(volume)); break;
    case VoxelType::UInt16: write_file_atomically(path, pack<std::uint16_t>(volume)); break;
    case VoxelType::Float32: write_file_atomically(path, pack<float>(volume)); break;
  }
}

}  // namespace grainlab::ct
