// Shared by the CT tests: the synthetic scans (made once per test binary) and
// the matching of segmented grains to the true ones.
#pragma once

#include "ct/segmentation.h"
#include "ct/synthetic_volume.h"
#include "geometry/mass_properties.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <limits>
#include <string>
#include <vector>

namespace grainlab::ct::testing {

// The standard scan: 112^3, 10 grains (ellipsoids, rounded, sub-angular, concave), two touching pairs.
inline const SyntheticScene& standard_scene() {
  static const SyntheticScene scene = make_synthetic_scene(SyntheticSpec{});
  return scene;
}

// A small scan for the format round trips: 56^3, two touching grains and one apart.
inline const SyntheticScene& small_scene() {
  static const SyntheticScene scene = [] {
    SyntheticSpec s;
    s.size = 56;
    s.grains = 3;
    s.touching_pairs = 1;
    s.grain_size = 16;
    s.seed = 3;
    return make_synthetic_scene(s);
  }();
  return scene;
}

// For each true grain, the index of the segmented grain with the nearest centroid.
inline std::vector<int> match_grains(const SyntheticScene& scene, const Segmentation& seg) {
  std::vector<int> match;
  for (const SyntheticGrain& t : scene.grains) {
    const Vec3 c = mass_properties(t.mesh).centroid;
    int best = -1;
    double best_d = std::numeric_limits<double>::max();
    for (int i = 0; i < static_cast<int>(seg.grains.size()); ++i) {
      const double d = (seg.grains[i].centroid - c).norm();
      if (d < best_d) {
        best_d = d;
        best = i;
      }
    }
    match.push_back(best);
  }
  return match;
}

// A fresh empty folder under the system's temporary folder.
inline std::filesystem::path fresh_folder(const std::string& name) {
  const auto p = std::filesystem::temp_directory_path() / ("grainlab_ct_test_" + name);
  std::filesystem::remove_all(p);
  std::filesystem::create_directories(p);
  return p;
}

}  // namespace grainlab::ct::testing
