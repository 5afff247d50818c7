// The part of a scan that is read: a crop box and a binning factor (--crop,
// --bin), applied slice by slice while reading so that a scan larger than
// memory can be segmented a piece at a time or at a coarser resolution.
//
// Crop: voxels lo <= (i, j, k) < hi are kept (half-open, as Python slices).
// Bin b: each output voxel is the mean of a b x b x b block of kept voxels,
// starting at lo; a remainder of fewer than b voxels along an axis is left
// out. Grid: voxel (0, 0, 0) of the output is centred at the mean of its
// block's centres, origin + D (s .* (lo + (b - 1) / 2)) for input origin,
// direction D and spacing s; the output spacing is b s.
#pragma once

#include "ct/volume.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace grainlab::ct {

struct CropBox {
  Size3 lo{0, 0, 0};  // first voxel kept
  Size3 hi{0, 0, 0};  // one past the last voxel kept
};

struct VolumeWindow {
  std::optional<CropBox> crop;
  int bin = 1;
  bool whole() const { return !crop && bin == 1; }
};

// "x0,y0,z0,x1,y1,z1" as given to --crop (six whole numbers); InputError otherwise.
CropBox parse_crop(const std::vector<std::int64_t>& values);

// The output size of `window` on an image of `full` voxels. Throws InputError
// naming --crop or --bin and the image's size when the box is not inside the
// image, empty, or binned to fewer than 2 voxels along an axis.
Size3 windowed_size(const Size3& full, const VolumeWindow& window, const std::string& image_name);

// The output grid: spacing, origin (see above) and size; direction unchanged.
template <typename T>
void apply_window_grid(Volume<T>& v, const VolumeWindow& window, const std::string& image_name) {
  const Size3 lo = window.crop ? window.crop->lo : Size3{0, 0, 0};
  const double half = (window.bin - 1) / 2.0;
  v.origin = v.world(Vec3(lo[0] + half, lo[1] + half, lo[2] + half));
  v.spacing *= window.bin;
  v.size = windowed_size(v.size, window, image_name);
}

// Fills slice z (0 <= z < full[2]) of the whole image: full[0] * full[1] values, x fastest.
using SliceReader = std::function<void(std::int64_t z, std::vector<float>& slice)>;

// The windowed voxels (x fastest), reading only the slices the window needs,
// one at a time: memory is the output plus one input slice and one output slice.
std::vector<float> read_windowed(const Size3& full, const VolumeWindow& window, const SliceReader& slice);

}  // namespace grainlab::ct
