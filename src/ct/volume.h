// A 3D image on a regular grid: grey levels of an X-ray CT scan, a binary
// mask or grain labels. Voxel (i, j, k) is the value at index
// i + nx (j + ny k); its centre lies at origin + direction (spacing .* (i, j, k))
// in world coordinates (metres), as in ITK, NRRD and MetaImage.
#pragma once

#include "core/types.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace grainlab::ct {

// Voxel counts along x, y, z.
using Size3 = std::array<std::int64_t, 3>;

template <typename T>
struct Volume {
  Size3 size{0, 0, 0};
  Vec3 spacing = Vec3::Ones();          // voxel edge lengths (m)
  Vec3 origin = Vec3::Zero();           // centre of voxel (0, 0, 0) (m)
  Mat3 direction = Mat3::Identity();    // columns: the image axes in world coordinates
  std::vector<T> values;                // size[0] * size[1] * size[2], x fastest

  std::int64_t voxel_count() const { return size[0] * size[1] * size[2]; }
  std::size_t index(std::int64_t i, std::int64_t j, std::int64_t k) const {
    return static_cast<std::size_t>(i + size[0] * (j + size[1] * k));
  }
  T& at(std::int64_t i, std::int64_t j, std::int64_t k) { return values[index(i, j, k)]; }
  const T& at(std::int64_t i, std::int64_t j, std::int64_t k) const { return values[index(i, j, k)]; }
  // World position (m) of a point given in continuous voxel indices.
  Vec3 world(const Vec3& ijk) const { return origin + direction * spacing.cwiseProduct(ijk); }
  // Makes `values` hold voxel_count() copies of `fill`.
  void allocate(T fill = T{}) { values.assign(static_cast<std::size_t>(voxel_count()), fill); }
  // Copies the grid (size, spacing, origin, direction) of another volume, not its values.
  template <typename U>
  void copy_grid(const Volume<U>& other) {
    size = other.size;
    spacing = other.spacing;
    origin = other.origin;
    direction = other.direction;
  }
};

using GreyVolume = Volume<float>;           // grey levels as read (any unit)
using MaskVolume = Volume<std::uint8_t>;    // 1 = solid, 0 = pore
using LabelVolume = Volume<std::uint32_t>;  // 0 = pore, 1..n = grain id

}  // namespace grainlab::ct
