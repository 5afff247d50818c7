// Mesh checks find each defect; repair fixes the safe ones and refuses the rest by name.
#include "geometry/mesh_check.h"

#include "geometry/mass_properties.h"
#include "geometry/mesh_io.h"
#include "geometry/primitives.h"
#include "test_helpers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <utility>

namespace grainlab {
namespace {

TriMesh open_box() {
  TriMesh m = box_mesh(1, 1, 1);
  m.faces.pop_back();
  return m;
}

// Two tetrahedra sharing only the edge (0,0,0)-(0,0,1): closed but non-manifold.
TriMesh two_tets_on_an_edge() {
  const TriMesh a = tetrahedron_mesh({0, 0, 0}, {0, 0, 1}, {1, 0, 0}, {0, 1, 0});
  const TriMesh b = tetrahedron_mesh({0, 0, 0}, {0, 0, 1}, {-1, 0, 0}, {0, -1, 0});
  TriMesh m = a;
  m.vertices.push_back(b.vertices[2]);
  m.vertices.push_back(b.vertices[3]);
  const Index remap[4] = {0, 1, 4, 5};
  for (const Face& f : b.faces) m.faces.push_back({remap[f[0]], remap[f[1]], remap[f[2]]});
  return m;
}

TEST(MeshCheck, CleanBoxPasses) {
  const MeshCheck c = check_mesh(box_mesh(1, 2, 3));
  EXPECT_TRUE(c.ok());
  EXPECT_EQ(c.describe(), "closed, manifold, outward");
  EXPECT_EQ(c.components, 1);
  EXPECT_NEAR(c.signed_volume, 48.0, 1e-12);
}

TEST(MeshCheck, OpenMeshFoundAndRefused) {
  const MeshCheck c = check_mesh(open_box());
  EXPECT_EQ(c.open_edges, 3);
  EXPECT_FALSE(c.ok());
  EXPECT_CONTAINS(c.describe(), "3 open edges (boundary)");
  const std::string msg = test::input_error_of([] { repair_mesh(open_box(), "grain_7.stl"); });
  EXPECT_CONTAINS(msg, "mesh 'grain_7.stl'");
  EXPECT_CONTAINS(msg, "open");
  EXPECT_CONTAINS(msg, "3 edges belong to only one face");
  EXPECT_CONTAINS(msg, "close the holes");
}

TEST(MeshCheck, OneFlippedFaceRepaired) {
  TriMesh m = box_mesh(1, 1, 1);
  std::swap(m.faces[4][1], m.faces[4][2]);
  const MeshCheck c = check_mesh(m);
  EXPECT_EQ(c.inconsistent_edges, 3);
  EXPECT_CONTAINS(c.describe(), "3 edges with inconsistent orientation");
  const TriMesh r = repair_mesh(m, "flipped.stl");
  const MeshCheck after = check_mesh(r);
  EXPECT_TRUE(after.ok()) << after.describe();
  EXPECT_NEAR(mass_properties(r).volume, 8.0, 1e-12);
}

TEST(MeshCheck, InvertedMeshRepairedToPositiveVolume) {
  TriMesh m = icosphere(1.0, 2);
  for (Face& f : m.faces) std::swap(f[0], f[1]);
  const MeshCheck c = check_mesh(m);
  EXPECT_TRUE(c.inside_out);
  EXPECT_EQ(c.inconsistent_edges, 0);
  EXPECT_CONTAINS(c.describe(), "inside out");
  const TriMesh r = repair_mesh(m, "inverted.stl");
  EXPECT_TRUE(check_mesh(r).ok());
  EXPECT_NEAR(mass_properties(r).volume, mass_properties(icosphere(1.0, 2)).volume, 1e-12);
}

TEST(MeshCheck, NonFiniteVertexRefused) {
  TriMesh m = box_mesh(1, 1, 1);
  m.vertices[3].z() = std::nan("");
  const MeshCheck c = check_mesh(m);
  EXPECT_EQ(c.non_finite_vertices, 1);
  EXPECT_CONTAINS(c.describe(), "1 non-finite vertex");
  const std::string msg = test::input_error_of([&] { repair_mesh(m, "nan.obj"); });
  EXPECT_CONTAINS(msg, "mesh 'nan.obj'");
  EXPECT_CONTAINS(msg, "1 vertex has non-finite");
}

TEST(MeshCheck, NonManifoldEdgeRefused) {
  const TriMesh m = two_tets_on_an_edge();
  const MeshCheck c = check_mesh(m);
  EXPECT_EQ(c.non_manifold_edges, 1);
  EXPECT_EQ(c.open_edges, 0);
  EXPECT_CONTAINS(c.describe(), "1 non-manifold edge");
  const std::string msg = test::input_error_of([&] { repair_mesh(m, "bowtie.ply"); });
  EXPECT_CONTAINS(msg, "mesh 'bowtie.ply'");
  EXPECT_CONTAINS(msg, "1 edge is shared by more than two faces");
  EXPECT_CONTAINS(msg, "non-manifold");
}

TEST(MeshCheck, DuplicateAndUnusedVerticesMerged) {
  // A box whose faces each own their three corners (as in an STL), one copy
  // nudged by far less than the merge tolerance, plus a stray unused vertex.
  const TriMesh box = box_mesh(1, 1, 1);
  TriMesh m;
  for (const Face& f : box.faces) {
    Face g{};
    for (int k = 0; k < 3; ++k) {
      g[k] = static_cast<Index>(m.vertices.size());
      m.vertices.push_back(box.vertices[f[k]]);
    }
    m.faces.push_back(g);
  }
  m.vertices[5].x() += 1e-12;
  m.vertices.emplace_back(0.1, 0.2, 0.3);
  const MeshCheck c = check_mesh(m);
  EXPECT_EQ(c.duplicate_vertices, 36 - 8);
  EXPECT_EQ(c.unused_vertices, 1);
  EXPECT_EQ(c.open_edges, 36);  // unmerged, every edge is open
  const TriMesh r = repair_mesh(m, "soup.stl");
  EXPECT_EQ(r.vertices.size(), 8u);
  EXPECT_EQ(r.faces.size(), 12u);
  EXPECT_TRUE(check_mesh(r).ok()) << check_mesh(r).describe();
  // A vertex farther than the tolerance is not merged.
  m.vertices[5].x() += 1e-6;
  EXPECT_EQ(check_mesh(m).duplicate_vertices, 36 - 9);
}

TEST(MeshCheck, RepeatedIndexFaceDropped) {
  TriMesh m = box_mesh(1, 1, 1);
  m.faces.push_back({2, 2, 5});
  const MeshCheck c = check_mesh(m);
  EXPECT_EQ(c.repeated_index_faces, 1);
  EXPECT_EQ(c.degenerate_faces, 1);
  EXPECT_FALSE(c.ok());
  const TriMesh r = repair_mesh(m, "x.stl");
  EXPECT_EQ(r.faces.size(), 12u);
  EXPECT_TRUE(check_mesh(r).ok());
}

TEST(MeshCheck, ZeroAreaFaceWithDistinctVerticesIsCountedButAllowed) {
  // Split the box's top face with a vertex on the edge between corners 4 and 5:
  // the face (4, m, 5) has zero area yet the surface stays closed.
  TriMesh m = box_mesh(1, 1, 1);
  const auto mid = static_cast<Index>(m.vertices.size());
  m.vertices.push_back((m.vertices[4] + m.vertices[5]) / 2);
  // Replace the y = -1 face pair (0,1,5),(0,5,4) and top pair (4,5,7),(4,7,6).
  m.faces[4] = {0, 1, 5};
  m.faces[5] = {0, 5, mid};
  m.faces.push_back({0, mid, 4});
  m.faces[2] = {4, mid, 7};
  m.faces[3] = {4, 7, 6};
  m.faces.push_back({mid, 5, 7});
  const MeshCheck c = check_mesh(m);
  EXPECT_EQ(c.degenerate_faces, 0);
  EXPECT_TRUE(c.ok()) << c.describe();
  // Now a true sliver: (4, mid, 5) is a zero-area face; closing it with (4, 5, mid) stays closed.
  TriMesh s = box_mesh(1, 1, 1);
  s.vertices.push_back((s.vertices[4] + s.vertices[5]) / 2);
  s.faces.push_back({4, mid, 5});
  s.faces.push_back({4, 5, mid});
  const MeshCheck cs = check_mesh(s);
  EXPECT_EQ(cs.degenerate_faces, 2);
  EXPECT_EQ(cs.non_manifold_edges, 1);  // edge 4-5 now has four faces
}

TEST(MeshCheck, EmptyAndZeroVolumeRefused) {
  EXPECT_CONTAINS(test::input_error_of([] { repair_mesh(TriMesh{}, "none.stl"); }), "mesh 'none.stl': the mesh is empty");
  const MeshCheck c = check_mesh(TriMesh{});
  EXPECT_FALSE(c.ok());
  EXPECT_CONTAINS(c.describe(), "empty");
  // A double-sided triangle: closed, consistent, encloses nothing.
  TriMesh flat;
  flat.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  flat.faces = {{0, 1, 2}, {0, 2, 1}};
  EXPECT_TRUE(check_mesh(flat).open_edges == 0);
  const std::string msg = test::input_error_of([&] { repair_mesh(flat, "flat.obj"); });
  EXPECT_CONTAINS(msg, "mesh 'flat.obj'");
  EXPECT_CONTAINS(msg, "zero volume");
  // Out-of-range index.
  TriMesh bad = box_mesh(1, 1, 1);
  bad.faces[0][2] = 99;
  EXPECT_EQ(check_mesh(bad).bad_indices, 1);
  EXPECT_CONTAINS(test::input_error_of([&] { repair_mesh(bad, "bad.obj"); }), "vertices that do not exist");
}

TEST(MeshCheck, TwoSeparateComponentsEachOutward) {
  TriMesh m = box_mesh(1, 1, 1);
  TriMesh b = box_mesh(0.5, 0.5, 0.5);
  const auto off = static_cast<Index>(m.vertices.size());
  for (const Vec3& v : b.vertices) m.vertices.push_back(v + Vec3(5, 0, 0));
  for (const Face& f : b.faces) m.faces.push_back({f[0] + off, f[2] + off, f[1] + off});  // inverted
  EXPECT_EQ(check_mesh(m).components, 2);
  const TriMesh r = repair_mesh(m, "two.stl");
  EXPECT_NEAR(mass_properties(r).volume, 8.0 + 1.0, 1e-12);
}

TEST(MeshCheck, LoadMeshNamesTheFile) {
  test::TempDir dir;
  write_stl(open_box(), dir / "holey.stl");
  const std::string msg = test::input_error_of([&] { load_mesh(dir / "holey.stl"); });
  EXPECT_CONTAINS(msg, "holey.stl");
  EXPECT_CONTAINS(msg, "open");

  write_stl(two_tets_on_an_edge(), dir / "bowtie.stl");
  EXPECT_CONTAINS(test::input_error_of([&] { load_mesh(dir / "bowtie.stl"); }), "non-manifold");

  // An inside-out sphere with one face flipped back: loads repaired and outward.
  TriMesh m = icosphere(1e-3, 2);
  for (Face& f : m.faces) std::swap(f[1], f[2]);
  std::swap(m.faces[17][1], m.faces[17][2]);
  write_obj(m, dir / "inverted.obj");
  std::vector<std::string> notes;
  const TriMesh r = load_mesh(dir / "inverted.obj", &notes);
  EXPECT_TRUE(check_mesh(r).ok());
  EXPECT_NEAR(mass_properties(r).volume / mass_properties(icosphere(1e-3, 2)).volume, 1.0, 1e-6);
  // Turned outward, and the user is told (a flipped mesh measured like the right one, silently).
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_CONTAINS(notes[0], "inverted.obj");
  EXPECT_CONTAINS(notes[0], "wound inward");
  // An outward mesh gets no note.
  notes.clear();
  write_obj(icosphere(1e-3, 2), dir / "outward.obj");
  load_mesh(dir / "outward.obj", &notes);
  EXPECT_TRUE(notes.empty());
}

}  // namespace
}  // namespace grainlab
