// Image files to volumes: header checks, units and the raw path here; ITK's
// readers and writers behind itk_bridge.h.
#include "core/text.h"
#include "ct/image_io.h"

#include "core/error.h"
#include "ct/itk_bridge.h"
#include "ct/nrrd_header.h"
#include "ct/raw_volume.h"
#include "ct/slice_stack.h"
#include "ct/temp_file.h"

#include <algorithm>
#include <cctype>
#include <cmath>

namespace grainlab::ct {

namespace fs = std::filesystem;

namespace {

constexpr double kMillimetre = 1e-3;  // the unit of the NRRD and MetaImage files grainlab writes

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
                h.format == "TIFF"                ? " (TIFF resolution tags are print densities, not voxel sizes)"
                : h.format == "raw"               ? " (a raw file has no header)"
                : h.format.find("slices") != std::string::npos ? " (2D slices carry no slice spacing)"
                                                  : " (its spacing is missing or exactly 1, ITK's placeholder)");
  }
}

// A voxel size outside what sand scans use is a unit mistake: refused with where it came from.
void check_plausible_spacing(const ImageSource& source, const ImageHeader& h) {
  const double lo = h.spacing.minCoeff(), hi = h.spacing.maxCoeff();
  if (lo >= kMinVoxelSize && hi <= kMaxVoxelSize) return;
  const double bad = lo < kMinVoxelSize ? lo : hi;
  if (source.voxel_size) {
    input_error("--voxel-size {:g} m ({:.6g} um) is outside the voxel sizes of sand scans ({:g} to {:g} um): give "
                "it in metres, e.g. --voxel-size 25e-6 for 25 micrometre voxels",
                *source.voxel_size, *source.voxel_size * 1e6, kMinVoxelSize * 1e6, kMaxVoxelSize * 1e6);
  }
  input_error("'{}' ({}) gives voxels of {:.6g} um ({:.6g} x {:.6g} x {:.6g} um, from its {}), outside the voxel "
              "sizes of sand scans ({:g} to {:g} um): its unit is probably not the one read ({}); give the voxel "
              "size with --voxel-size in metres (e.g. --voxel-size 25e-6 for 25 micrometre voxels){}",
              source.path.string(), h.format, bad * 1e6, h.spacing[0] * 1e6, h.spacing[1] * 1e6,
              h.spacing[2] * 1e6, h.spacing_source, kMinVoxelSize * 1e6, kMaxVoxelSize * 1e6,
              bad < kMinVoxelSize ? "sizes written in metres and read as mm come out 1000 times too small"
                                  : "sizes written in mm or um and read as m or mm come out 1000 times too large",
              h.format == "NRRD" ? ", or name the unit in the header (space units: \"m\" \"m\" \"m\")" : "");
}

ImageHeader read_itk_header(const ImageSource& source) {
  const std::string path = source.path.string();
  // NRRD: the unit and the data's length, which ITK neither passes on nor checks (MetaImage, TIFF: itk_bridge).
  NrrdUnits units;
  units.source = "header field 'ElementSpacing' read as mm (MetaImage has no unit field)";
  if (itk_bridge::format_for(path) == "NRRD") {
    const NrrdHeader nh = read_nrrd_header(source.path);
    check_nrrd_data_size(nh, source.path);
    units = nrrd_units(nh, source.path);
  }
  const itk_bridge::Header ih = itk_bridge::read_header(path);
  ImageHeader h;
  h.format = ih.format;
  if (ih.dimensions != 3) {
    std::string shape;
    for (std::size_t a = 0; a < ih.extent.size(); ++a) shape += (a ? " x " : "") + std::to_string(ih.extent[a]);
    input_error("'{}' is not a 3D image: it holds a {}D image ({} voxels); a CT volume needs a stack of slices "
                "(multi-page TIFF, NRRD or MetaImage with three dimensions, or a folder of 2D slices)",
                path, ih.dimensions, shape);
  }
  if (ih.components != 1) {
    input_error("'{}' has {} components per voxel (colour or vector); a CT volume has one grey level per voxel: "
                "convert it to greyscale first",
                path, ih.components);
  }
  bool unit_spacing = true;
  for (int a = 0; a < 3; ++a) {
    h.size[a] = ih.grid.size[a];
    h.spacing[a] = ih.grid.spacing[a] * units.metres_per_unit[a];
    h.origin[a] = ih.grid.origin[a] * units.metres_per_unit[a];
    for (int r = 0; r < 3; ++r) h.direction(r, a) = ih.grid.direction[3 * a + r];
    if (ih.grid.spacing[a] != 1.0) unit_spacing = false;
  }
  check_size(source, h.size);
  const bool file_has_spacing = h.format != "TIFF" && (units.named || !unit_spacing);
  if (!source.voxel_size && file_has_spacing && !(h.spacing.minCoeff() > 0 && h.spacing.allFinite())) {
    input_error("'{}' gives a voxel spacing of ({}, {}, {}) in its header; it must be positive: fix the header or "
                "give --voxel-size",
                path, ih.grid.spacing[0], ih.grid.spacing[1], ih.grid.spacing[2]);
  }
  if (h.format == "TIFF") h.origin.setZero();
  h.spacing_source = units.source;
  settle_spacing(source, h, file_has_spacing);
  return h;
}

ImageHeader read_stack_header(const ImageSource& source, const SliceStack& stack) {
  ImageHeader h;
  h.format = stack.format + " slices";
  h.size = stack.size;
  check_size(source, h.size);
  settle_spacing(source, h, false);
  return h;
}

// The header of the whole file, before the window.
ImageHeader read_stored_header(const ImageSource& source) {
  std::error_code ec;
  if (!fs::exists(source.path, ec)) input_error("image '{}' does not exist", source.path.string());
  if (fs::is_directory(source.path, ec)) {
    if (source.raw) input_error("'{}' is a folder: --size and --type are for one raw file", source.path.string());
    return read_stack_header(source, scan_slice_folder(source.path));
  }
  if (fs::is_regular_file(source.path, ec) && fs::file_size(source.path, ec) == 0) {
    input_error("image '{}' is empty (0 bytes): write it again", source.path.string());
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
  if (itk_bridge::format_for(source.path.string()).empty() || itk_bridge::format_for(source.path.string()) == "PNG") {
    const std::string ext = lower(source.path.extension().string());
    if (ext == ".raw" || ext == ".bin" || ext == ".vol") {
      input_error("'{}' is a raw file: give its layout with --size NX NY NZ and --type uint8|uint16|float32 (and "
                  "--voxel-size), or write a .mhd header for it",
                  source.path.string());
    }
    input_error("'{}': unknown image format '{}'; grainlab reads multi-page TIFF (.tif, .tiff), NRRD (.nrrd, "
                ".nhdr), MetaImage (.mha, .mhd), a folder of 2D TIFF or PNG slices, and headerless raw files (give "
                "--size NX NY NZ and --type)",
                source.path.string(), ext.empty() ? "(no extension)" : ext);
  }
  return read_itk_header(source);
}

template <typename V>
void set_grid(V& volume, const ImageHeader& h) {
  volume.size = h.size;
  volume.spacing = h.spacing;
  volume.origin = h.origin;
  volume.direction = h.direction;
}

// The window's voxels: slice by slice from a slice folder or a raw file; an
// ITK file is read whole (its readers give no slices) and then windowed.
std::vector<float> read_values(const ImageSource& source, const ImageHeader& h) {
  const Size3& full = h.stored_size;
  if (fs::is_directory(source.path)) {
    const SliceStack stack = scan_slice_folder(source.path);
    return read_windowed(full, source.window, [&](std::int64_t z, std::vector<float>& s) { read_slice(stack, z, s); });
  }
  if (source.raw) {
    return read_windowed(full, source.window,
                         [&](std::int64_t z, std::vector<float>& s) { read_raw_slice(source.path, *source.raw, z, s); });
  }
  std::vector<float> all = itk_bridge::read_values(source.path.string());
  if (source.window.whole()) return all;
  const std::size_t n = static_cast<std::size_t>(full[0] * full[1]);
  return read_windowed(full, source.window, [&](std::int64_t z, std::vector<float>& s) {
    std::copy_n(all.begin() + static_cast<std::ptrdiff_t>(z * n), n, s.begin());
  });
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

itk_bridge::Stored stored_type(VoxelType type) {
  switch (type) {
    case VoxelType::UInt8: return itk_bridge::Stored::UInt8;
    case VoxelType::UInt16: return itk_bridge::Stored::UInt16;
    case VoxelType::Float32: return itk_bridge::Stored::Float32;
  }
  return itk_bridge::Stored::Float32;
}

// Grey levels converted to what `type` stores (rounded and clamped for integers), held as float.
std::vector<float> as_stored(std::vector<float>::const_iterator begin, std::vector<float>::const_iterator end,
                             VoxelType type) {
  std::vector<float> values(begin, end);
  for (float& v : values) {
    if (type == VoxelType::UInt8) v = to_voxel<std::uint8_t>(v);
    if (type == VoxelType::UInt16) v = to_voxel<std::uint16_t>(v);
  }
  return values;
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
  if (source.voxel_size && !(*source.voxel_size > 0 && std::isfinite(*source.voxel_size))) {
    input_error("--voxel-size {} is not a positive length in metres (e.g. 25e-6)", *source.voxel_size);
  }
  ImageHeader h = read_stored_header(source);
  check_plausible_spacing(source, h);
  h.stored_size = h.size;
  if (!source.window.whole()) {
    GreyVolume grid;  // the grid alone, to move it by the window
    set_grid(grid, h);
    apply_window_grid(grid, source.window, source.path.string());
    h.size = grid.size;
    h.spacing = grid.spacing;
    h.origin = grid.origin;
    if (!fs::is_directory(source.path) && !source.raw) {
      h.read_buffer_bytes = static_cast<std::uint64_t>(h.stored_size[0]) * h.stored_size[1] * h.stored_size[2] *
                            sizeof(float);
    }
  }
  return h;
}

GreyVolume read_grey_volume(const ImageSource& source) {
  const ImageHeader h = read_image_header(source);
  GreyVolume v;
  set_grid(v, h);
  v.values = read_values(source, h);
  return v;
}

LabelVolume read_label_volume(const ImageSource& source) {
  if (source.window.bin != 1) {
    input_error("--bin {} averages grey levels, and a label image (--labels) cannot be averaged: crop it with --crop "
                "instead, or bin the grey-level scan",
                source.window.bin);
  }
  const ImageHeader h = read_image_header(source);
  const std::vector<float> values = read_values(source, h);
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
  const std::string ext = lower(path.extension().string());
  if (ext == ".raw") {
    write_raw_volume(volume, path, type);
    return;
  }
  if (ext == ".mhd" || ext == ".nhdr" || itk_bridge::format_for(path.string()).empty()) {
    input_error("'{}': grainlab writes grey volumes as .tif, .nrrd, .mha or .raw", path.string());
  }
  const itk_bridge::Stored stored = stored_type(type);
  const std::vector<float> values = as_stored(volume.values.begin(), volume.values.end(), type);
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

void write_grey_slices(const GreyVolume& volume, const fs::path& folder, const std::string& prefix,
                       const std::string& extension, VoxelType type) {
  std::error_code ec;
  fs::create_directories(folder, ec);
  if (ec) input_error("cannot create the slice folder '{}': {}", folder.string(), ec.message());
  const std::size_t n = static_cast<std::size_t>(volume.size[0] * volume.size[1]);
  for (std::int64_t z = 0; z < volume.size[2]; ++z) {
    const auto begin = volume.values.begin() + static_cast<std::ptrdiff_t>(z * n);
    const fs::path path = folder / fmt::format("{}{:04d}{}", prefix, z, extension);
    itk_bridge::write_slice(path.string(), volume.size[0], volume.size[1],
                            as_stored(begin, begin + static_cast<std::ptrdiff_t>(n), type), stored_type(type));
  }
}

void write_label_volume(const LabelVolume& labels, const fs::path& path) {
  const std::string ext = lower(path.extension().string());
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
