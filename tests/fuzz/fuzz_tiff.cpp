// Fuzz harness: a multi-page TIFF scan (ct/image_io.h): the header is read and checked
// (grainlab's own checks before ITK's reader), and when the image is
// small (at most 64^3 voxels), its voxels are read too. See harness_input.h.
#include "ct/image_io.h"
#include "fuzz/harness_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  grainlab::ct::ImageSource source;
  source.path = grainlab::fuzz::input_file({data, size}, "scan.tif");
  source.voxel_size = 20e-6;  // as --voxel-size gives it: a TIFF has none
  return grainlab::fuzz::refused_or_read([&] {
    const grainlab::ct::ImageHeader header = grainlab::ct::read_image_header(source);
    if (header.size[0] * header.size[1] * header.size[2] <= 64 * 64 * 64) grainlab::ct::read_grey_volume(source);
  });
}
