// Image files to volumes: header checks, units and the raw path here; ITK's
// readers and writers behind itk_bridge.h.
#include "ct/image_io.h"

#include "core/error.h"
#include "ct/itk_bridge.h"
#include "ct/raw_volume.h"
#include "ct/temp_file.h"

#include <algorithm>
#include <cctype>
#include <cmath>

namespace grainlab::ct {

namespace fs = std::filesystem;

namespace {

constexpr double kMillimetre = 1e-3;  // NRRD and MetaImage spacing and origin unit

std::string lower_extension(const fs::path& p) {
  std::string ext = p.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

void check_size(const ImageSource& source, const Size3& size) {
  for (int a = 0; a < 3; ++a) {
    if (size[a] < 2) {
      input_error("'{}' is not a 3D image: {} x {} x {} voxels; a CT volume needs at least 2 voxels along x, y and "
                  "z (a single slice is a 2D image: stack the slices into a multi-page TIFF, NRRD or MetaImage)",
                  source.path.string(), size[0], size[1], size[2]);
    }
  }
}

// Applies --voxel-size, or checks that the file gave one.
void settle_spacing(const ImageSource& source, ImageHeader& h, bool file_has_spacing) {
  if (source.voxel_size) {
    h.spacing = Vec3::Constant(*source.voxel_size);
    h.spacing_source = "--voxel-size";
    return;
  }
  if (!file_has_spacing) {
    input_error("'{}' ({}) does not give a voxel size{}: give it with --voxel-size in metres (e.g. --voxel-size "
                "25e-6 for 25 micrometre voxels)",
                source.path.string(), h.format,
                h.format == "TIFF"  ? " (TIFF resolution tags are print densities, not voxel sizes)"
                : h.format == "raw" ? " (a raw file has no header)"
                                    : " (its spacing is missing or exactly 1, ITK's placeholder)");
  }
  h.spacing_source = "file";
}

ImageHeader read_itk_header(const ImageSource& source) {
  const itk_bridge::Header ih = itk_bridge::read_header(source.path.string());
  ImageHeader h;
  h.format = ih.format;
  if (ih.dimensions != 3) {
    std::string shape;
    for (std::size_t a = 0; a < ih.extent.size(); ++a) shape += (a ? " x " : "") + std::to_string(ih.extent[a]);
    input_error("'{}' is not a 3D image: it holds a {}D image ({} voxels); a CT volume needs a stack of slices "
                "(multi-page TIFF, NRRD or MetaImage with three dimensions)",
                source.path.string(), ih.dimensions, shape);
  }
  if (ih.components != 1) {
    input_error("'{}' has {} components per voxel (colour or vector); a CT volume has one grey level per voxel: "
                "convert it to greyscale first",
                source.path.string(), ih.components);
  }
  bool unit_spacing = true;
  for (int a = 0; a < 3; ++a) {
    h.size[a] = ih.grid.size[a];
    h.spacing[a] = ih.grid.spacing[a] * kMillimetre;
    h.origin[a] = ih.grid.origin[a] * kMillimetre;
    for (int r = 0; r < 3; ++r) h.direction(r, a) = ih.grid.direction[3 * a + r];
    if (ih.grid.spacing[a] != 1.0) unit_spacing = false;
  }
  check_size(source, h.size);
  const bool file_has_spacing = h.format != "TIFF" && !unit_spacing;
  if (!source.voxel_size && file_has_spacing && !(h.spacing.minCoeff() > 0 && h.spacing.allFinite())) {
    input_error("'{}' gives a voxel spacing of ({}, {}, {}) mm; it must be positive: fix the header or give "
                "--voxel-size",
                source.path.string(), ih.grid.spacing[0], ih.grid.spacing[1], ih.grid.spacing[2]);
  }
  if (h.format == "TIFF") h.origin.setZero();
  settle_spacing(source, h, file_has_spacing);
  return h;
}

template <typename V>
void set_grid(V& volume, const ImageHeader& h) {
  volume.size = h.size;
  volume.spacing = h.spacing;
  volume.origin = h.origin;
  volume.direction = h.direction;
}

std::vector<float> read_values(const ImageSource& source) {
  return source.raw ? read_raw_values(source.path, *source.raw) : itk_bridge::read_values(source.path.string());
}

template <typename V>
itk_bridge::Grid bridge_grid(const V& v) {
  itk_bridge::Grid g;
  for (int a = 0; a < 3; ++a) {
    g.size[a] = v.size[a];
    g.spacing[a] = v.spacing[a] / kMillimetre;
    g.origin[a] = v.origin[a] / kMillimetre;
    for (int r = 0; r < 3; ++r) g.direction[3 * a + r] = v.direction(r, a);
  }
  return g;
}

}  // namespace

VoxelType parse_voxel_type(const std::string& name) {
  if (name == "uint8") return VoxelType::UInt8;
  if (name == "uint16") return VoxelType::UInt16;
  if (name == "float32") return VoxelType::Float32;
  input_error("unknown voxel type '{}': use uint8, uint16 or float32", name);
}

const char* voxel_type_name(VoxelType type) {
  switch (type) {
    case VoxelType::UInt8: return "uint8";
    case VoxelType::UInt16: return "uint16";
    case VoxelType::Float32: return "float32";
  }
  return "?";
}

int voxel_bytes(VoxelType type) { return type == VoxelType::UInt8 ? 1 : type == VoxelType::UInt16 ? 2 : 4; }

ImageHeader read_image_header(const ImageSource& source) {
  std::error_code ec;
  if (!fs::exists(source.path, ec)) input_error("image '{}' does not exist", source.path.string());
  if (fs::is_regular_file(source.path, ec) && fs::file_size(source.path, ec) == 0) {
    input_error("image '{}' is empty (0 bytes): write it again", source.path.string());
  }
  if (source.voxel_size && !(*source.voxel_size > 0 && std::isfinite(*source.voxel_size))) {
    input_error("--voxel-size {} is not a positive length in metres (e.g. 25e-6)", *source.voxel_size);
  }
  if (source.raw) {
    ImageHeader h;
    h.format = "raw";
    h.size = source.raw->size;
    check_size(source, h.size);
    check_raw_file(source.path, *source.raw);
    settle_spacing(source, h, false);
    return h;
  }
  if (itk_bridge::format_for(source.path.string()).empty()) {
    const std::string ext = lower_extension(source.path);
    if (ext == ".raw" || ext == ".bin" || ext == ".vol") {
      input_error("'{}' is a raw file: give its layout with --size NX NY NZ and --type uint8|uint16|float32 (and "
                  "--voxel-size), or write a .mhd header for it",
                  source.path.string());
    }
    input_error("'{}': unknown image format '{}'; grainlab reads multi-page TIFF (.tif, .tiff), NRRD (.nrrd, "
                ".nhdr), MetaImage (.mha, .mhd) and headerless raw files (give --size NX NY NZ and --type)",
                source.path.string(), ext.empty() ? "(no extension)" : ext);
  }
  return read_itk_header(source);
}

GreyVolume read_grey_volume(const ImageSource& source) {
  const ImageHeader h = read_image_header(source);
  GreyVolume v;
  set_grid(v, h);
  v.values = read_values(source);
  return v;
}

LabelVolume read_label_volume(const ImageSource& source) {
  const ImageHeader h = read_image_header(source);
  const std::vector<float> values = read_values(source);
  LabelVolume v;
  set_grid(v, h);
  v.values.resize(values.size());
  constexpr float kMaxExact = 16777216.0f;  // 2^24: floats hold every whole number below it
  for (std::size_t i = 0; i < values.size(); ++i) {
    const float x = values[i];
    if (!(x >= 0 && x < kMaxExact && x == std::floor(x))) {
      input_error("'{}' is not a label image: voxel {} holds {} (labels are whole numbers, 0 = pore, 1, 2, ... = "
                  "grains, below 2^24); for a grey-level scan leave out --labels",
                  source.path.string(), i, x);
    }
    v.values[i] = static_cast<std::uint32_t>(x);
  }
  return v;
}

void write_grey_volume(const GreyVolume& volume, const fs::path& path, VoxelType type) {
  const std::string ext = lower_extension(path);
  if (ext == ".raw") {
    write_raw_volume(volume, path, type);
    return;
  }
  if (ext == ".mhd" || ext == ".nhdr" || itk_bridge::format_for(path.string()).empty()) {
    input_error("'{}': grainlab writes grey volumes as .tif, .nrrd, .mha or .raw", path.string());
  }
  std::vector<float> values(volume.values.size());
  itk_bridge::Stored stored = itk_bridge::Stored::Float32;
  switch (type) {
    case VoxelType::UInt8:
      std::transform(volume.values.begin(), volume.values.end(), values.begin(),
                     [](float v) { return static_cast<float>(to_voxel<std::uint8_t>(v)); });
      stored = itk_bridge::Stored::UInt8;
      break;
    case VoxelType::UInt16:
      std::transform(volume.values.begin(), volume.values.end(), values.begin(),
                     [](float v) { return static_cast<float>(to_voxel<std::uint16_t>(v)); });
      stored = itk_bridge::Stored::UInt16;
      break;
    case VoxelType::Float32: values = volume.values; break;
  }
  const fs::path tmp = temporary_sibling(path);
  try {
    itk_bridge::write_values(tmp.string(), bridge_grid(volume), values, stored, false);
  } catch (...) {
    std::error_code ec;
    fs::remove(tmp, ec);
    throw;
  }
  commit_temporary(tmp, path);
}

void write_label_volume(const LabelVolume& labels, const fs::path& path) {
  const std::string ext = lower_extension(path);
  if (ext != ".nrrd" && ext != ".mha") input_error("'{}': label images are written as .nrrd or .mha", path.string());
  const fs::path tmp = temporary_sibling(path);
  try {
    itk_bridge::write_labels(tmp.string(), bridge_grid(labels), labels.values, true);
  } catch (...) {
    std::error_code ec;
    fs::remove(tmp, ec);
    throw;
  }
  commit_temporary(tmp, path);
}

}  // namespace grainlab::ct
