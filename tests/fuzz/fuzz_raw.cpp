// Fuzz harness: a headerless raw scan (ct/raw_volume.h), read with the layout
// a user gives on the command line (--size, --type). The first 4 bytes of the
// input choose that layout (nx, ny, nz from 1 to 256 each, and the voxel
// type), the rest is the file; a voxel size is given as --voxel-size would,
// and when the image is small (at most 64^3 voxels) its voxels are read.
// See harness_input.h.
#include "ct/image_io.h"
#include "fuzz/harness_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 4) return 0;
  grainlab::ct::RawLayout layout;
  layout.size = {data[0] + 1, data[1] + 1, data[2] + 1};
  constexpr grainlab::ct::VoxelType kTypes[] = {grainlab::ct::VoxelType::UInt8, grainlab::ct::VoxelType::UInt16,
                                                grainlab::ct::VoxelType::Float32};
  layout.type = kTypes[data[3] % 3];
  grainlab::ct::ImageSource source;
  source.path = grainlab::fuzz::input_file({data + 4, size - 4}, "scan.raw");
  source.raw = layout;
  source.voxel_size = 20e-6;
  return grainlab::fuzz::refused_or_read([&] {
    const grainlab::ct::ImageHeader header = grainlab::ct::read_image_header(source);
    if (header.size[0] * header.size[1] * header.size[2] <= 64 * 64 * 64) grainlab::ct::read_grey_volume(source);
  });
}
