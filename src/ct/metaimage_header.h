// The MetaImage (.mha, .mhd) header fields grainlab reads itself, to check
// that uncompressed binary data holds exactly the voxels the header
// describes (declared_data.h): DimSize, ElementType,
// ElementNumberOfChannels, CompressedData, BinaryData, HeaderSize and
// ElementDataFile ("LOCAL": the data follows the header; a file name: a
// detached data file, after HeaderSize bytes, -1 meaning at its end).
// Format: itk.org/Wiki/ITK/MetaIO/Documentation.
#pragma once

#include <filesystem>

namespace grainlab::ct {

// Throws InputError naming the file, both lengths and the fields to fix when
// the data is shorter or longer than DimSize x channels x ElementType's bytes.
// Compressed, ASCII and multi-file data are left to ITK's reader.
void check_metaimage_data_size(const std::filesystem::path& path);

}  // namespace grainlab::ct
