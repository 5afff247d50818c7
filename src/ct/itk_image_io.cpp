// ITK's readers and writers behind itk_bridge.h: each format's ImageIO object
// is named explicitly (no factory registration), and ITK's exceptions become
// InputError or RunError messages naming the file.
#include "ct/itk_bridge.h"

#include "core/error.h"
#include "ct/metaimage_header.h"
#include "ct/tiff_structure.h"

#include <itkImage.h>
#include <itkImageFileReader.h>
#include <itkImageFileWriter.h>
#include <itkMetaImageIO.h>
#include <itkNrrdImageIO.h>
#include <itkPNGImageIO.h>
#include <itkTIFFImageIO.h>

#include <algorithm>
#include <cctype>

namespace grainlab::ct::itk_bridge {

namespace {

std::string lower_extension(const std::string& path) {
  const auto dot = path.find_last_of('.');
  const auto slash = path.find_last_of('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string ext = path.substr(dot);
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

itk::ImageIOBase::Pointer image_io_for(const std::string& path) {
  const std::string f = format_for(path);
  if (f == "TIFF") return itk::TIFFImageIO::New().GetPointer();
  if (f == "NRRD") return itk::NrrdImageIO::New().GetPointer();
  if (f == "MetaImage") return itk::MetaImageIO::New().GetPointer();
  if (f == "PNG") return itk::PNGImageIO::New().GetPointer();
  input_error("'{}': no ITK reader for this extension", path);
}

// The reason in an ITK exception's description, without ITK's "ITK ERROR:
// Class(0x...): " prefix. NRRD errors come as a chain of teem messages
// ("[nrrd] function: message"), the last one the cause: "Read: Error reading
// f.nrrd: fread got only 64000 2-sized things, not 128000 (50% of expected)".
std::string reason(const itk::ExceptionObject& e) {
  std::vector<std::string> lines;
  std::string d = e.GetDescription();
  for (std::size_t start = 0; start < d.size();) {
    const auto nl = d.find('\n', start);
    std::string line = d.substr(start, nl == std::string::npos ? std::string::npos : nl - start);
    start = nl == std::string::npos ? d.size() : nl + 1;
    if (line.find_first_not_of(" \t\r") != std::string::npos) lines.push_back(line);
  }
  if (lines.empty()) return "no reason given by ITK";
  std::string first = lines.front();
  const auto paren = first.find("): ");
  if (first.find("ERROR") != std::string::npos && paren != std::string::npos) first = first.substr(paren + 3);
  if (lines.size() == 1) return first;
  std::string cause = lines.back();
  if (cause.rfind("[", 0) == 0) {  // "[nrrd] function: message"
    const auto colon = cause.find(": ");
    cause = colon == std::string::npos ? cause : cause.substr(colon + 2);
  }
  if (!first.empty() && first.back() == ':') first.pop_back();
  return first + ": " + cause;
}

using FloatImage = itk::Image<float, 3>;

// Writes `image` in the format `path`'s extension names (zlib where the format has it and `compress`).
template <typename Image>
void write_image(const std::string& path, const typename Image::Pointer& image, bool compress) {
  itk::ImageIOBase::Pointer io = image_io_for(path);
  io->SetUseCompression(compress);
  auto writer = itk::ImageFileWriter<Image>::New();
  writer->SetImageIO(io);
  writer->SetFileName(path);
  writer->SetInput(image);
  try {
    writer->Update();
  } catch (const itk::ExceptionObject& e) {
    throw RunError(fmt::format("cannot write '{}': {}", path, reason(e)));
  }
}

template <typename T, typename In>
void write_as(const std::string& path, const Grid& grid, const std::vector<In>& values, bool compress) {
  using Image = itk::Image<T, 3>;
  auto image = Image::New();
  typename Image::SizeType size;
  typename Image::SpacingType spacing;
  typename Image::PointType origin;
  typename Image::DirectionType direction;
  for (unsigned a = 0; a < 3; ++a) {
    size[a] = static_cast<itk::SizeValueType>(grid.size[a]);
    spacing[a] = grid.spacing[a];
    origin[a] = grid.origin[a];
    for (unsigned r = 0; r < 3; ++r) direction(r, a) = grid.direction[3 * a + r];
  }
  image->SetRegions(size);
  image->SetSpacing(spacing);
  image->SetOrigin(origin);
  image->SetDirection(direction);
  image->Allocate();
  std::transform(values.begin(), values.end(), image->GetBufferPointer(), [](In v) { return static_cast<T>(v); });
  write_image<Image>(path, image, compress);
}

std::string component_name(itk::IOComponentEnum t) {
  switch (t) {
    case itk::IOComponentEnum::UCHAR: return "uint8";
    case itk::IOComponentEnum::CHAR: return "int8";
    case itk::IOComponentEnum::USHORT: return "uint16";
    case itk::IOComponentEnum::SHORT: return "int16";
    case itk::IOComponentEnum::UINT: return "uint32";
    case itk::IOComponentEnum::INT: return "int32";
    case itk::IOComponentEnum::ULONG:
    case itk::IOComponentEnum::ULONGLONG: return "uint64";
    case itk::IOComponentEnum::LONG:
    case itk::IOComponentEnum::LONGLONG: return "int64";
    case itk::IOComponentEnum::FLOAT: return "float32";
    case itk::IOComponentEnum::DOUBLE: return "float64";
    default: return "unknown";
  }
}

template <typename T>
void write_slice_as(const std::string& path, std::int64_t nx, std::int64_t ny, const std::vector<float>& values) {
  using Image = itk::Image<T, 2>;
  auto image = Image::New();
  typename Image::SizeType size;
  size[0] = static_cast<itk::SizeValueType>(nx);
  size[1] = static_cast<itk::SizeValueType>(ny);
  image->SetRegions(size);
  image->Allocate();
  std::transform(values.begin(), values.end(), image->GetBufferPointer(), [](float v) { return static_cast<T>(v); });
  write_image<Image>(path, image, false);
}

// grainlab's own strict reading of the structures ITK's MetaImage and TIFF
// readers trust (a malformed header made them read past their buffers);
// `voxels`: before the voxels are read (a MetaImage's compressed data is
// inflated then, not when only its header is read).
void check_before_itk(const std::string& path, bool voxels) {
  const std::string f = format_for(path);
  if (f == "TIFF") check_tiff_structure(path);
  if (f == "MetaImage") check_metaimage_header(path, voxels);
}

}  // namespace

std::string format_for(const std::string& path) {
  const std::string ext = lower_extension(path);
  if (ext == ".tif" || ext == ".tiff") return "TIFF";
  if (ext == ".png") return "PNG";
  if (ext == ".nrrd" || ext == ".nhdr") return "NRRD";
  if (ext == ".mha" || ext == ".mhd") return "MetaImage";
  return "";
}

Header read_header(const std::string& path) {
  check_before_itk(path, false);
  Header h;
  h.format = format_for(path);
  itk::ImageIOBase::Pointer io = image_io_for(path);
  io->SetFileName(path);
  try {
    if (!io->CanReadFile(path.c_str())) {
      input_error("'{}' is not a readable {} file (a damaged or truncated header, or the wrong extension)", path,
                  h.format);
    }
    io->ReadImageInformation();
  } catch (const itk::ExceptionObject& e) {
    input_error("cannot read '{}' as {}: {}", path, h.format, reason(e));
  }
  h.dimensions = io->GetNumberOfDimensions();
  h.components = io->GetNumberOfComponents();
  h.component_type = component_name(io->GetComponentType());
  for (unsigned a = 0; a < h.dimensions; ++a) h.extent.push_back(static_cast<std::int64_t>(io->GetDimensions(a)));
  if (h.dimensions == 3) {
    for (unsigned a = 0; a < 3; ++a) {
      h.grid.size[a] = h.extent[a];
      h.grid.spacing[a] = io->GetSpacing(a);
      h.grid.origin[a] = io->GetOrigin(a);
      const std::vector<double> d = io->GetDirection(a);
      for (unsigned r = 0; r < 3; ++r) h.grid.direction[3 * a + r] = d[r];
    }
  }
  return h;
}

std::vector<float> read_values(const std::string& path) {
  check_before_itk(path, true);
  auto reader = itk::ImageFileReader<FloatImage>::New();
  reader->SetImageIO(image_io_for(path));
  reader->SetFileName(path);
  try {
    reader->Update();
  } catch (const itk::ExceptionObject& e) {
    input_error("cannot read the voxels of '{}' (a truncated or damaged file?): {}", path, reason(e));
  }
  FloatImage* image = reader->GetOutput();
  const float* p = image->GetBufferPointer();
  return std::vector<float>(p, p + image->GetLargestPossibleRegion().GetNumberOfPixels());
}

void write_values(const std::string& path, const Grid& grid, const std::vector<float>& values, Stored stored,
                  bool compress) {
  switch (stored) {
    case Stored::UInt8: write_as<std::uint8_t>(path, grid, values, compress); break;
    case Stored::UInt16: write_as<std::uint16_t>(path, grid, values, compress); break;
    case Stored::UInt32: write_as<std::uint32_t>(path, grid, values, compress); break;
    case Stored::Float32: write_as<float>(path, grid, values, compress); break;
  }
}

void write_slice(const std::string& path, std::int64_t nx, std::int64_t ny, const std::vector<float>& values,
                 Stored stored) {
  if (format_for(path) == "PNG" && (stored == Stored::Float32 || stored == Stored::UInt32)) {
    input_error("'{}': PNG holds 8- and 16-bit grey levels only: write float slices as TIFF", path);
  }
  switch (stored) {
    case Stored::UInt8: write_slice_as<std::uint8_t>(path, nx, ny, values); break;
    case Stored::UInt16: write_slice_as<std::uint16_t>(path, nx, ny, values); break;
    case Stored::UInt32: write_slice_as<std::uint32_t>(path, nx, ny, values); break;
    case Stored::Float32: write_slice_as<float>(path, nx, ny, values); break;
  }
}

void write_labels(const std::string& path, const Grid& grid, const std::vector<std::uint32_t>& values,
                  bool compress) {
  const std::uint32_t top = values.empty() ? 0 : *std::max_element(values.begin(), values.end());
  if (top <= 65535) {
    write_as<std::uint16_t>(path, grid, values, compress);
  } else {
    write_as<std::uint32_t>(path, grid, values, compress);
  }
}

}  // namespace grainlab::ct::itk_bridge
