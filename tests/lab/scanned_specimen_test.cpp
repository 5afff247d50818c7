// A specimen from a segmented scan (scanned_specimen.h): a hand-made scan
// folder (meshes in world coordinates and grains.csv, as `grainlab ct
// segment` writes them) of four grains, one touching the image border and
// two overlapping by 20 um (a box's end pushed into an ellipsoid), as
// segmented neighbours can.
//  - Each grain is placed with its scanned orientation: its posed surface is
//    the scanned mesh, moved; the centroids keep their relative positions up
//    to the reported spread factor; after the spread nothing overlaps by more
//    than kScanOverlap of a diameter; the border grain is dropped unless kept.
//  - The run goes straight to consolidation, and reports the scan's void ratio.
//  - A box smaller than the scan is refused with the size it needs.
#include "core/error.h"
#include "geometry/mass_properties.h"
#include "geometry/mesh_io.h"
#include "geometry/primitives.h"
#include "lab/direct_shear.h"
#include "lab/scanned_specimen.h"
#include "tiny_box.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

using namespace grainlab;

namespace {

struct ScanDir {
  std::filesystem::path path;
  std::vector<TriMesh> meshes;  // as scanned (world coordinates)
  ScanDir() {
    path = std::filesystem::temp_directory_path() / ("grainlab-scan-" + std::to_string(::getpid()));
    std::filesystem::remove_all(path);
    std::filesystem::create_directories(path);
    const double mm = 1e-3;
    const auto posed = [&](TriMesh m, const Quat& q, const Vec3& x) {
      for (Vec3& v : m.vertices) v = q * (v * mm) + x;
      return m;
    };
    meshes.push_back(posed(ellipsoid_mesh(0.5, 0.35, 0.3, 2),
                           Quat(Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized())), Vec3(1.0, 1.0, 1.0) * mm));
    double right = -INFINITY;  // the first grain's largest x
    for (const Vec3& v : meshes[0].vertices) right = std::max(right, v.x());
    // 0.02 mm into the first grain along x (the box's half length is 0.4 mm).
    meshes.push_back(posed(box_mesh(0.4, 0.1, 0.1), Quat::Identity(), Vec3(right + (0.4 - 0.02) * mm, 1.0 * mm, 1.0 * mm)));
    meshes.push_back(posed(ellipsoid_mesh(0.4, 0.4, 0.3, 2), Quat(Eigen::AngleAxisd(-1.1, Vec3::UnitY())),
                           Vec3(1.2, 2.2, 1.1) * mm));
    meshes.push_back(posed(ellipsoid_mesh(0.3, 0.3, 0.3, 2), Quat::Identity(), Vec3(0.3, 0.3, 0.3) * mm));
    std::ofstream csv(path / "grains.csv");
    csv << "id,file,x_m,y_m,z_m,qw,qx,qy,qz,volume_m3,equivalent_diameter_m,border\n";
    for (std::size_t k = 0; k < meshes.size(); ++k) {
      const std::string file = "grain_000" + std::to_string(k + 1) + ".stl";
      write_stl(meshes[k], path / file);
      const Vec3 c = mass_properties(meshes[k]).centroid;
      csv << k + 1 << ',' << file << ',' << c.x() << ',' << c.y() << ',' << c.z() << ",1,0,0,0,0,0,"
          << (k == 3 ? 1 : 0) << '\n';
    }
  }
  ~ScanDir() {
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
  }
};

LabSpec scan_spec(const ScanDir& d) {
  LabSpec s = testing_support::tiny_box_spec();
  s.grains.scan = d.path.string();
  s.box.length = s.box.width = 4e-3;
  return s;
}

double summary_of(const LabTest& t, const std::string& group, const std::string& key) {
  for (const SummaryValue& v : t.summary())
    if (v.group == group && v.key == key) return v.value;
  ADD_FAILURE() << group << "." << key << " missing";
  return 0;
}

}  // namespace

TEST(ScannedSpecimen, GrainsArePlacedAsScannedSpreadApartAndConsolidated) {
  const ScanDir scan;
  DirectShearTest t(scan_spec(scan));
  const World& w = t.world();
  ASSERT_EQ(w.model.bodies.size(), 3u);  // the border grain dropped
  EXPECT_EQ(summary_of(t, "scan", "border_grains_dropped"), 1);
  const double f = summary_of(t, "scan", "position_spread");
  EXPECT_GT(f, 1.0);  // the overlap of 20 um needs a spread
  EXPECT_TRUE(std::find(std::begin(kScanSpreads), std::end(kScanSpreads), f) != std::end(kScanSpreads));

  std::vector<Vec3> scanned_centroid;
  for (int k = 0; k < 3; ++k) scanned_centroid.push_back(mass_properties(scan.meshes[k]).centroid);
  for (int k = 0; k < 3; ++k) {
    // Relative positions: the scan's, times the spread.
    for (int j = k + 1; j < 3; ++j)
      EXPECT_NEAR((w.state.bodies[j].x - w.state.bodies[k].x - f * (scanned_centroid[j] - scanned_centroid[k])).norm(),
                  0, 1e-9);  // STL stores float32: 1e-10 m at these sizes
    // Orientation: the posed shape is the scanned mesh, moved to the body's centroid.
    const Shape& shape = w.model.shapes[w.model.bodies[k].shape];
    for (const Vec3& v : scan.meshes[k].vertices) {
      double nearest = INFINITY;
      for (const Vec3& u : shape.mesh.vertices)
        nearest = std::min(nearest, (w.state.bodies[k].q * u + scanned_centroid[k] - v).norm());
      ASSERT_LT(nearest, 1e-9) << "grain " << k;
    }
  }
  // The scan's void ratio: its grains' bounding box over their volume.
  Vec3 lo = Vec3::Constant(INFINITY), hi = -lo;
  double solid = 0;
  for (int k = 0; k < 3; ++k) {
    for (const Vec3& v : scan.meshes[k].vertices) {
      lo = lo.cwiseMin(v);
      hi = hi.cwiseMax(v);
    }
    solid += mass_properties(scan.meshes[k]).volume;
  }
  EXPECT_NEAR(summary_of(t, "scan", "void_ratio"), (hi - lo).prod() / solid - 1, 1e-6);  // float32 files
  // After the spread no two grains overlap by more than kScanOverlap of a diameter.
  World& wm = t.world();
  wm.step(1e-30);
  const double d = t.summary().empty() ? 0 : summary_of(t, "", "mean_equivalent_diameter_m");
  for (const Contact& c : wm.state.contacts) EXPECT_LE(c.geo.depth, kScanOverlap * d);
  // No deposition or compaction: consolidation first.
  EXPECT_EQ(t.phase_name(), "consolidate");
}

TEST(ScannedSpecimen, BorderGrainsAreKeptWhenAsked) {
  const ScanDir scan;
  LabSpec s = scan_spec(scan);
  s.grains.scan_border = "keep";
  DirectShearTest t(s);
  EXPECT_EQ(t.world().model.bodies.size(), 4u);
}

TEST(ScannedSpecimen, ABoxSmallerThanTheScanIsRefusedWithTheSizeItNeeds) {
  const ScanDir scan;
  LabSpec s = scan_spec(scan);
  s.box.length = 1.5e-3;
  try {
    DirectShearTest t(s);
    FAIL() << "a 1.5 mm box took a scan 2.3 mm across";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("box.length >="), std::string::npos) << e.what();
  }
}
