// Reading and writing 3D CT images: multi-page TIFF, NRRD (.nrrd, .nhdr),
// MetaImage (.mha, or a .mhd header next to its raw data) through ITK, and
// headerless raw files (--size, --type) with grainlab's own reader.
//
// Units. grainlab works in metres. NRRD and MetaImage files carry a voxel
// spacing and an origin but no unit; they are read as millimetres, the
// convention of ITK, 3D Slicer and the medical formats (grainlab writes them
// so). A spacing of exactly 1 along every axis is what ITK reports when a file
// gives none, so it counts as unknown. TIFF resolution tags are dots per inch
// for printing, not voxel sizes, and raw files have no header: for those the
// voxel size must come from the command line (--voxel-size, which also wins
// over any file's).
#pragma once

#include "ct/volume.h"

#include <filesystem>
#include <optional>
#include <string>

namespace grainlab::ct {

// Voxel types of raw files (and of what write_grey_volume stores).
enum class VoxelType { UInt8, UInt16, Float32 };

// "uint8" | "uint16" | "float32"; InputError listing them otherwise.
VoxelType parse_voxel_type(const std::string& name);
const char* voxel_type_name(VoxelType type);
int voxel_bytes(VoxelType type);

// The layout of a headerless raw file: nx * ny * nz voxels, x fastest, little endian.
struct RawLayout {
  Size3 size{0, 0, 0};
  VoxelType type = VoxelType::UInt16;
};

// Where an image comes from and what the user said about it.
struct ImageSource {
  std::filesystem::path path;
  std::optional<RawLayout> raw;      // set: read `path` as raw whatever its extension
  std::optional<double> voxel_size;  // m, cubic voxels; wins over the file's spacing
};

// What a file holds, from its header alone (nothing large is read).
struct ImageHeader {
  std::string format;                // "TIFF", "NRRD", "MetaImage", "raw"
  Size3 size{0, 0, 0};
  Vec3 spacing = Vec3::Ones();       // m, after --voxel-size or the file's (see units above)
  Vec3 origin = Vec3::Zero();        // m
  Mat3 direction = Mat3::Identity();
  std::string spacing_source;        // "--voxel-size" or "file"
};

// Reads and checks the header: a 3D single-component image of at least 2
// voxels along each axis, with a known voxel size. Throws InputError naming the
// file, what is wrong and how to fix it (empty file, unknown extension, 2D
// image, raw file size not matching --size and --type, no voxel size).
ImageHeader read_image_header(const ImageSource& source);

// Reads the grey levels (any integer or float voxel type, converted to float).
GreyVolume read_grey_volume(const ImageSource& source);

// Reads an already-labelled image: 0 = pore, 1, 2, ... = grains. Throws
// InputError when a value is negative or not a whole number.
LabelVolume read_label_volume(const ImageSource& source);

// Writes grey levels as `type` (rounded and clamped for integers), the format
// chosen by the extension: .tif/.tiff (multi-page, no voxel size), .nrrd,
// .mha, .raw (no header: read it back with --size and --type). Spacing and
// origin go in millimetres. Through a temporary file renamed into place.
void write_grey_volume(const GreyVolume& volume, const std::filesystem::path& path, VoxelType type);

// Writes a label image (uint16 when the largest label fits, else uint32) as
// .nrrd or .mha, through a temporary file renamed into place.
void write_label_volume(const LabelVolume& labels, const std::filesystem::path& path);

}  // namespace grainlab::ct
