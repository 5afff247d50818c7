// A synthetic CT scan of elongated, dented grains packed in touching clusters
// (pairs and triples), with the true label of every voxel: the hard case for
// a distance-map watershed, where two elongated grains lying side by side
// touch along a neck almost as thick as the grains themselves.
//
// Each grain is a superellipsoid |x/a|^p + |y/b|^p + |z/c|^p <= 1 (p = 2,
// 3 or 4: an ellipsoid to flat-flanked; semi-axes a >= b >= c; intermediate
// dimension 2b = `grain_size` (1 +- size_spread), aspect a/b uniform in
// [aspect_min, aspect_max], c/b in [0.75, 0.95]) with a dent: a ball of
// radius 0.5-0.8 b cut out of one flank, 0.2-0.35 b deep. Grains come in
// clusters (sizes cycling 3, 2, 2, 1): the first grain of a cluster is
// placed at random, 2 voxels from the grains of other clusters; each next
// one touches the one before (and must not overlap the rest of its
// cluster), half of them side by side (long axes parallel within 10
// degrees, flank facing flank: a wide flat neck, the hard case), half at
// random. The touching distance is found by bisection (sampled overlap on a
// 0.5-voxel grid), then the grain is moved closer by a press uniform in
// [-0.5, press_max] voxels (negative: a gap the blur bridges), so necks
// range from a voxel thick to several, and from a point to most of a flank
// wide. A cluster whose next grain finds no room is placed again.
// Occupancy is sampled s^3 times per voxel (a voxel sure to be wholly in or
// out, by the superellipsoid's level along its ray, is not sampled, unless
// another grain may share it). Where pressed grains overlap, a sample
// belongs to the grain it lies deepest in, so the grains partition the
// solid: the truth label of a voxel is the grain owning most of it (when it
// owns at least half), the true volume of a grain the sum of what it owns.
// (Counting the overlap in both grains' volumes, as before 2026-12-06, made
// a small grain pressed 2.5 voxels into a larger one up to 1.5 % larger than
// any segmentation of the scan can find it.)
#pragma once

#include "ct/volume.h"

#include <cstdint>
#include <vector>

namespace grainlab::ct {

struct PackedPhantomSpec {
  std::int64_t size = 160;     // voxels along each side (a cube)
  double voxel_size = 25e-6;   // m
  int grains = 18;
  double grain_size = 36;      // voxels: intermediate dimension 2b (+-15 %)
  double aspect_min = 1.5, aspect_max = 2.5;  // a / b
  double size_spread = 0.15;   // 2b uniform in grain_size (1 +- size_spread)
  double press_max = 1.0;      // voxels: the most a touching grain is pressed into its partner
  std::uint64_t seed = 1;
  double blur = 1.0;           // voxels: Gaussian standard deviation
  double noise = 0.04;         // standard deviation, fraction of solid - pore
  int samples = 3;             // sub-samples per voxel edge
};

struct PackedPhantom {
  GreyVolume volume;            // pore 10000, solid 40000 grey levels
  LabelVolume truth;            // 0 = pore, 1..n = grain
  std::vector<double> volumes;  // true volume of grain g (index g - 1), m^3: its share of the solid
};

// Throws RunError when the grains do not fit (a larger size helps).
PackedPhantom make_packed_phantom(const PackedPhantomSpec& spec);

}  // namespace grainlab::ct
