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

// Reads slice z (nx * ny voxels, x fastest) of a checked raw file as float.
void read_raw_slice(const std::filesystem::path& path, const RawLayout& layout, std::int64_t z,
                    std::vector<float>& values);

// Writes the voxels as `type` (integers rounded and clamped), atomically.
void write_raw_volume(const GreyVolume& volume, const std::filesystem::path& path, VoxelType type);

// A grey value converted to a stored type: rounded and clamped for integers.
template <typename T>
T to_voxel(float v);

}  // namespace grainlab::ct
