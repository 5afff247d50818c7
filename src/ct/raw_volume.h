// Headerless raw volumes: nx * ny * nz voxels of one type, x fastest, little
// endian, nothing else in the file. Read and written without ITK.
#pragma once

#include "ct/image_io.h"

#include <filesystem>
#include <vector>

namespace grainlab::ct {

// Checks that `path` holds exactly the bytes `layout` needs (InputError
// naming both sizes otherwise: empty, truncated or too long).
void check_raw_file(const std::filesystem::path& path, const RawLayout& layout);

// Reads a checked raw file's voxels as float.
std::vector<float> read_raw_values(const std::filesystem::path& path, const RawLayout& layout);

// Writes the voxels as `type` (integers rounded and clamped), atomically.
void write_raw_volume(const GreyVolume& volume, const std::filesystem::path& path, VoxelType type);

// A grey value converted to a stored type: rounded and clamped for integers.
template <typename T>
T to_voxel(float v);

}  // namespace grainlab::ct
