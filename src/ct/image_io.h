// Reading and writing 3D CT images: multi-page TIFF, NRRD (.nrrd, .nhdr),
// MetaImage (.mha, or a .mhd header next to its raw data) through ITK, a
// folder of 2D TIFF or PNG slices (slice_stack.h), and headerless raw files
// (--size, --type) with grainlab's own reader.
//
// Units. grainlab works in metres. An NRRD file's spacing and origin are in
// its "space units" (or per-axis "units") when it gives them, in millimetres
// when not; MetaImage has no unit field and is read as millimetres, the
// convention of ITK, 3D Slicer and the medical formats (grainlab writes both
// so). A spacing of exactly 1 along every axis with no unit is what ITK
// reports when a file gives none, so it counts as unknown. TIFF resolution
// tags are dots per inch for printing, not voxel sizes, and raw files and
// slice folders have no voxel size: for those it must come from the command
// line (--voxel-size, which also wins over any file's). A voxel size outside
// kMinVoxelSize..kMaxVoxelSize is refused, wherever it comes from: it is a
// unit mistake (a file written in metres read as mm gives 0.025 um voxels).
#pragma once

#include "ct/volume.h"
#include "ct/volume_window.h"

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
  VolumeWindow window;               // the part read (--crop, --bin)
};

// Voxel sizes of sand scans, from nano-CT to a coarse lab scan (m).
inline constexpr double kMinVoxelSize = 0.1e-6;
inline constexpr double kMaxVoxelSize = 1e-3;

// What a file holds, from its header alone (nothing large is read).
// What a file holds, from its header alone (nothing large is read), after the window.
struct ImageHeader {
  std::string format;                // "TIFF", "NRRD", "MetaImage", "raw", "TIFF slices", "PNG slices"
  Size3 size{0, 0, 0};               // voxels read (after --crop and --bin)
  Size3 stored_size{0, 0, 0};        // voxels in the file
  Vec3 spacing = Vec3::Ones();       // m, after --voxel-size or the file's (see units above), and --bin
  Vec3 origin = Vec3::Zero();        // m: centre of the first voxel read
  Mat3 direction = Mat3::Identity();
  std::string spacing_source;        // "--voxel-size" or the header field and unit it came from
  std::uint64_t read_buffer_bytes = 0;  // held while reading besides the volume: a whole ITK file before its window
};

// Reads and checks the header: a 3D single-component image of at least 2
// voxels along each axis, with a plausible voxel size. Throws InputError
// naming the file, what is wrong and how to fix it (empty file, unknown
// extension, 2D image, raw, NRRD or MetaImage data size not matching the layout, no
// voxel size, an unknown unit, a voxel size outside kMinVoxelSize..
// kMaxVoxelSize, a bad slice folder, a window outside the image).
ImageHeader read_image_header(const ImageSource& source);

// Reads the grey levels (any integer or float voxel type, converted to float),
// the window applied. A slice folder or raw file is read one slice at a time.
GreyVolume read_grey_volume(const ImageSource& source);

// Reads an already-labelled image: 0 = pore, 1, 2, ... = grains. Throws
// InputError when a value is negative or not a whole number, or --bin is
// asked (labels cannot be averaged; --crop is fine).
LabelVolume read_label_volume(const ImageSource& source);

// Writes grey levels as `type` (rounded and clamped for integers), the format
// chosen by the extension: .tif/.tiff (multi-page, no voxel size), .nrrd,
// .mha, .raw (no header: read it back with --size and --type). Spacing and
// origin go in millimetres. Through a temporary file renamed into place.
void write_grey_volume(const GreyVolume& volume, const std::filesystem::path& path, VoxelType type);

// Writes `volume` as one 2D slice per z into `folder` (created): `prefix`,
// the slice number from 0 (4 digits or more), `extension` (".tif" or ".png";
// PNG holds uint8 and uint16 only). No voxel size is stored.
void write_grey_slices(const GreyVolume& volume, const std::filesystem::path& folder, const std::string& prefix,
                       const std::string& extension, VoxelType type);

// Writes a label image (uint16 when the largest label fits, else uint32) as
// .nrrd or .mha, through a temporary file renamed into place.
void write_label_volume(const LabelVolume& labels, const std::filesystem::path& path);

}  // namespace grainlab::ct
