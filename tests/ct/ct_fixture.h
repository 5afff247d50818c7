// Shared by the CT tests: the synthetic scans (made once per test binary) and
// the matching of segmented grains to the true ones.
#pragma once

#include "ct/raw_volume.h"
#include "ct/segmentation.h"
#include "ct/synthetic_volume.h"
#include "file_text.h"
#include "geometry/mass_properties.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include <sys/wait.h>

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

// The scan as stored in uint16 (what the files of the format tests hold).
inline GreyVolume as_uint16(const GreyVolume& v) {
  GreyVolume out = v;
  for (float& x : out.values) x = to_voxel<std::uint16_t>(x);
  return out;
}

// Writes `v` (origin 0, identity direction) as an NRRD file with raw uint16
// data, its header written here: `sizes` as given (the data's size unless a
// test lies), each voxel edge printed as `edge` (the number, in the unit the
// header's extra `fields` name, e.g. "space units: \"m\" \"m\" \"m\"\n").
inline void write_nrrd_by_hand(const std::filesystem::path& path, const GreyVolume& v, const Size3& sizes,
                               double edge, const std::string& fields) {
  std::ofstream out(path, std::ios::binary);
  out << "NRRD0004\ntype: unsigned short\ndimension: 3\nspace: left-posterior-superior\n"
      << "sizes: " << sizes[0] << " " << sizes[1] << " " << sizes[2] << "\n";
  char d[200];
  std::snprintf(d, sizeof d, "space directions: (%.17g,0,0) (0,%.17g,0) (0,0,%.17g)\n", edge, edge, edge);
  out << d << fields << "kinds: domain domain domain\nendian: little\nencoding: raw\nspace origin: (0,0,0)\n\n";
  for (float x : v.values) {
    const std::uint16_t u = to_voxel<std::uint16_t>(x);
    char b[2];
    std::memcpy(b, &u, 2);
    out.write(b, 2);
  }
}

// Two segmentations of the same scan give the same grains: count, threshold,
// volumes, centroids and mesh sizes.
inline void expect_same_grains(const Segmentation& a, const Segmentation& b, const std::string& what) {
  ASSERT_EQ(a.grains.size(), b.grains.size()) << what;
  EXPECT_EQ(a.threshold, b.threshold) << what;
  for (std::size_t g = 0; g < a.grains.size(); ++g) {
    EXPECT_NEAR(a.grains[g].volume / b.grains[g].volume, 1.0, 1e-9) << what;
    EXPECT_LT((a.grains[g].centroid - b.grains[g].centroid).norm(), 1e-12) << what;
    EXPECT_EQ(a.grains[g].mesh.faces.size(), b.grains[g].mesh.faces.size()) << what;
  }
}

struct Outcome {
  int code = 0;
  std::string err;
};

// Runs the grainlab binary with `args`, returning its exit code and standard error.
inline Outcome run_grainlab(const std::string& args, const std::filesystem::path& dir) {
  const std::filesystem::path err = dir / "stderr.txt";
  const std::string cmd = std::string(GRAINLAB_BINARY) + " " + args + " > /dev/null 2> " + err.string();
  const int status = std::system(cmd.c_str());
  return {WEXITSTATUS(status), grainlab::test::file_text(err)};
}

// A fresh empty folder under the system's temporary folder.
inline std::filesystem::path fresh_folder(const std::string& name) {
  const auto p = std::filesystem::temp_directory_path() / ("grainlab_ct_test_" + name);
  std::filesystem::remove_all(p);
  std::filesystem::create_directories(p);
  return p;
}

}  // namespace grainlab::ct::testing
