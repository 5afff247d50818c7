#include "ct/volume_window.h"

#include "core/error.h"

namespace grainlab::ct {

CropBox parse_crop(const std::vector<std::int64_t>& v) {
  if (v.size() != 6) {
    input_error("--crop takes six whole numbers x0,y0,z0,x1,y1,z1 (voxels; x0 <= x < x1 is kept), not {}",
                v.size());
  }
  return CropBox{{v[0], v[1], v[2]}, {v[3], v[4], v[5]}};
}

Size3 windowed_size(const Size3& full, const VolumeWindow& w, const std::string& image_name) {
  if (w.bin < 1) input_error("--bin {} must be a whole number of 1 or more (2: average 2x2x2 voxels)", w.bin);
  const CropBox box = w.crop ? *w.crop : CropBox{{0, 0, 0}, full};
  Size3 out{};
  for (int a = 0; a < 3; ++a) {
    if (!(box.lo[a] >= 0 && box.lo[a] < box.hi[a] && box.hi[a] <= full[a])) {
      input_error("--crop {},{},{},{},{},{} is not inside '{}' ({} x {} x {} voxels): give 0 <= x0 < x1 <= {}, "
                  "0 <= y0 < y1 <= {}, 0 <= z0 < z1 <= {} (voxels x0 to x1 - 1 are kept)",
                  box.lo[0], box.lo[1], box.lo[2], box.hi[0], box.hi[1], box.hi[2], image_name, full[0], full[1],
                  full[2], full[0], full[1], full[2]);
    }
    out[a] = (box.hi[a] - box.lo[a]) / w.bin;
    if (out[a] < 2) {
      input_error("'{}' cropped and binned leaves {} voxel(s) along {}: a CT volume needs at least 2; crop a larger "
                  "box or bin less",
                  image_name, out[a], "xyz"[a]);
    }
  }
  return out;
}

std::vector<float> read_windowed(const Size3& full, const VolumeWindow& w, const SliceReader& slice) {
  const Size3 out = windowed_size(full, w, "the image");
  const Size3 lo = w.crop ? w.crop->lo : Size3{0, 0, 0};
  const std::int64_t b = w.bin;
  const std::size_t out_slice = static_cast<std::size_t>(out[0] * out[1]);
  std::vector<float> values(out_slice * static_cast<std::size_t>(out[2]));
  std::vector<float> in;
  std::vector<double> sum(out_slice);
  const double scale = 1.0 / static_cast<double>(b * b * b);
  for (std::int64_t k = 0; k < out[2]; ++k) {
    std::fill(sum.begin(), sum.end(), 0.0);
    for (std::int64_t dz = 0; dz < b; ++dz) {
      in.assign(static_cast<std::size_t>(full[0] * full[1]), 0.0f);
      slice(lo[2] + k * b + dz, in);
      for (std::int64_t j = 0; j < out[1] * b; ++j) {
        const float* row = in.data() + (lo[1] + j) * full[0] + lo[0];
        double* target = sum.data() + (j / b) * out[0];
        for (std::int64_t i = 0; i < out[0] * b; ++i) target[i / b] += row[i];
      }
    }
    float* dst = values.data() + static_cast<std::size_t>(k) * out_slice;
    for (std::size_t n = 0; n < out_slice; ++n) dst[n] = static_cast<float>(sum[n] * scale);
  }
  return values;
}

}  // namespace grainlab::ct
