// The only door to ITK. ITK 5.2 bundles its own Eigen 3.3, which cannot share a
// translation unit with the system Eigen 3.4 that core/types.h brings, so the
// two ITK files (itk_image_io.cpp, itk_watershed.cpp) see only this header:
// plain arrays and vectors, no Eigen. Everything else in src/ct calls these.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace grainlab::ct::itk_bridge {

// A grid as ITK gives it: spacing and origin in the file's unit (mm by the
// formats' convention), direction cosines column by column (column a = image axis a).
struct Grid {
  std::array<std::int64_t, 3> size{0, 0, 0};
  std::array<double, 3> spacing{1, 1, 1};
  std::array<double, 3> origin{0, 0, 0};
  std::array<double, 9> direction{1, 0, 0, 0, 1, 0, 0, 0, 1};
};

// "TIFF", "NRRD", "MetaImage", "PNG" (2D slices only) for a known extension, "" otherwise.
std::string format_for(const std::string& path);

// What an image file's header says.
struct Header {
  std::string format;
  unsigned dimensions = 0;            // 2 for a single slice
  std::vector<std::int64_t> extent;   // voxels along each dimension
  unsigned components = 1;            // 3 for RGB
  std::string component_type;         // as stored: "uint8", "uint16", "float32", "int16", ...
  Grid grid;                          // valid when dimensions == 3
};

// Reads a header (format chosen by extension). Throws InputError naming the file.
Header read_header(const std::string& path);

// Reads every voxel as float, x fastest. Throws InputError naming the file.
std::vector<float> read_values(const std::string& path);

// Voxel types written.
enum class Stored { UInt8, UInt16, UInt32, Float32 };

// Writes voxels (x fastest, already converted to the stored type's range and
// held in float or uint32) to `path` in the format its extension names;
// `compress` asks for zlib where the format has it. Throws RunError.
void write_values(const std::string& path, const Grid& grid, const std::vector<float>& values, Stored stored,
                  bool compress);
void write_labels(const std::string& path, const Grid& grid, const std::vector<std::uint32_t>& values,
                  bool compress);

// Writes one 2D slice of nx x ny voxels (x fastest) as TIFF or PNG (by the
// extension; PNG holds only uint8 and uint16). Throws RunError.
void write_slice(const std::string& path, std::int64_t nx, std::int64_t ny, const std::vector<float>& values,
                 Stored stored);

// Progress callback: fraction done, 0-1.
using ProgressFn = std::function<void(double)>;

// Splits a binary mask (1 = solid) into grains: Euclidean distance map inside
// the solid (in voxels), h-maxima of depth h (voxels) as markers, marker
// watershed of the negated distance, restricted to the solid. Every
// 26-connected solid component gets at least one marker.
//
// h > 0 is used as given. h = 0 chooses it from the scan: r_typ, the median
// over the solid components (a grain, or grains touching) of the largest
// inscribed radius (the distance map's top, specks of a voxel left out),
// sets h = max(kMinDepth, kDepthPerRadius r_typ). The spurious hills (a
// grain's facets and lobes) grow with the voxels per grain, and so does the
// rise of a grain above its contact necks, so one fixed depth cannot serve
// every scan: on six synthetic scans per size (docs/ct.md, step 3), h = 2
// merged touching grains in 7 of 12 scans at 14-18 voxels across and split
// one at 72; a fifth of r_typ found every grain in all 24 scans at 14, 18,
// 36 and 72 voxels, the working depths spanning about 0.12-0.28 r_typ.
inline constexpr double kMinDepth = 1.0;
inline constexpr double kDepthPerRadius = 0.2;

struct Watershed {
  std::vector<std::uint32_t> labels;  // 1..n (0 = pore), in no particular order
  double h = 0;                       // the depth used (voxels)
  double typical_radius = 0;          // r_typ (voxels) when h was chosen from the scan, else 0
  std::vector<float> distance;        // with over_split_h > 0: distance to the pore (voxels), 0 in the pore
};

// over_split_h > 0: the markers are the hills deeper than over_split_h instead
// of h (an over-split for neck_merge.h to merge back; h is still chosen and
// reported as above) and the distance map is kept.
Watershed distance_watershed(const std::vector<std::uint8_t>& mask, const std::array<std::int64_t, 3>& size, double h,
                             const ProgressFn& progress, double over_split_h = 0);

// One grain's hills in the distance map of `mask` (1 = the grain, 0 = anything
// else; give it a margin of pore): its largest inscribed radius (voxels) and,
// for h > 0, how many hills rise more than h above their saddles, the markers
// the watershed above would give this grain alone (at least 1).
struct Hills {
  double radius = 0;
  int count = 1;
};
Hills distance_hills(const std::vector<std::uint8_t>& mask, const std::array<std::int64_t, 3>& size, double h);

}  // namespace grainlab::ct::itk_bridge
