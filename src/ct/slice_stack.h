// A folder of 2D slices (TIFF or PNG, one file per z) read as one volume.
//
// The slices are the folder's .tif/.tiff or .png files (other files, hidden
// files and subfolders are ignored), ordered by the number in their names:
// the last run of digits that differs between the files (scan_0012_v2.tif:
// 12), so slice_9.tif comes before slice_10.tif whatever the zero padding. The numbers must run without a gap and all names must
// share the text around the number (one series per folder). Every slice must
// be a single-channel 2D image of the same width, height and pixel type. Only
// the headers are read here; the voxels are read slice by slice (read_slice).
#pragma once

#include "ct/volume.h"

#include <filesystem>
#include <string>
#include <vector>

namespace grainlab::ct {

struct SliceStack {
  std::vector<std::filesystem::path> files;  // slice z is files[z]
  std::int64_t first_number = 0;             // the number in files[0]'s name
  Size3 size{0, 0, 0};                       // width, height, number of slices
  std::string format;                        // "TIFF" or "PNG"
  std::string pixel_type;                    // "uint8", "uint16", "float32", ...
};

// Lists and checks the slices. Throws InputError naming the folder and the
// offending files: no slices, a name without a number, two series, a
// repeated number, a gap in the numbering, TIFF and PNG mixed, a slice that is
// not a 2D single-channel image, or slices of different sizes or pixel types.
SliceStack scan_slice_folder(const std::filesystem::path& folder);

// The number in a slice file's name and the text around it ("scan_", ".tif"
// for scan_0012.tif -> 12): the last run of digits, or with run_from_end = 1
// the one before it (scan_0012_v2.tif -> 12), ...; number -1 when there is no
// such run.
struct SliceName {
  std::string before, after;
  std::int64_t number = -1;
};
SliceName parse_slice_name(const std::string& filename, int run_from_end = 0);

// Slice z's voxels as float (size[0] * size[1], x fastest).
void read_slice(const SliceStack& stack, std::int64_t z, std::vector<float>& values);

}  // namespace grainlab::ct
