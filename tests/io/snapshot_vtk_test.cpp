// Snapshot files of a tiny hand-built world (two spheres, two convex grains, a
// plane and a box wall, one step so that contacts and forces exist): every
// grain's mesh is there with its id and values, one line per grain-grain
// contact, every wall, and .pvd collections listing each snapshot and time.
#include "io/snapshot_vtk.h"

#include "dynamics/world.h"
#include "geometry/primitives.h"
#include "core/atomic_file.h"
#include "io/pvd_reader.h"
#include "io/vtp_reader.h"
#include "io_test_helpers.h"
#include "vtk_test_helpers.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace grainlab {
namespace {

const VtkArray& array_named(const std::vector<VtkArray>& arrays, const std::string& name) {
  for (const VtkArray& a : arrays)
    if (a.name == name) return a;
  ADD_FAILURE() << "no array '" << name << "'";
  static const VtkArray none;
  return none;
}

template <typename T>
const std::vector<T>& values(const std::vector<VtkArray>& arrays, const std::string& name) {
  const VtkArray& a = array_named(arrays, name);
  static const std::vector<T> none;
  const auto* v = std::get_if<std::vector<T>>(&a.values);
  if (!v) ADD_FAILURE() << "array '" << name << "' has type " << a.type_name();
  return v ? *v : none;
}

Vec3 point(const PolyData& pd, std::size_t i) {
  const auto& p = std::get<std::vector<double>>(pd.points.values);
  return Vec3(p[3 * i], p[3 * i + 1], p[3 * i + 2]);
}

// Grains 0 and 1 (spheres, r = 1 mm) overlap each other and rest in the plane z = 0; grain 2 (a convex 42-vertex grain) presses on grain 0 from
// above; grain 3 (the same shape at scale 0.5, tilted) floats alone. A box wall lies below.
World tiny_world() {
  World w;
  Material m;
  m.youngs_modulus = 1e7;
  const Index mat = w.model.add_material(m);
  const Index ball = w.model.add_sphere_shape(1e-3, "ball");
  const Index grain = w.model.add_mesh_shape(icosphere(1e-3, 1), "grain");
  w.add_body(ball, mat, 1.0, Vec3(0, 0, 0.99e-3));
  w.add_body(ball, mat, 1.0, Vec3(1.9e-3, 0, 0.99e-3));
  w.add_body(grain, mat, 1.0, Vec3(0, 0, 2.8e-3));
  w.add_body(grain, mat, 0.5, Vec3(6e-3, 6e-3, 6e-3), Quat(Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized())));
  w.add_plane(Vec3::Zero(), Vec3::UnitZ(), mat, "floor");
  w.add_box_wall(Vec3(0, 0, -10e-3), Vec3(5e-3, 4e-3, 1e-3), Quat(Eigen::AngleAxisd(0.2, Vec3::UnitZ())), mat, "slab");
  w.step(0.1 * w.critical_time_step());
  return w;
}

std::size_t vertex_count(const Model& model, Index body, int sphere_subdivisions = 2) {
  const Shape& s = model.shapes[model.bodies[body].shape];
  return s.kind == Shape::Kind::Sphere ? icosphere(1, sphere_subdivisions).vertices.size() : s.mesh.vertices.size();
}
std::size_t face_count(const Model& model, Index body) {
  const Shape& s = model.shapes[model.bodies[body].shape];
  return s.kind == Shape::Kind::Sphere ? icosphere(1, 2).faces.size() : s.mesh.faces.size();
}

TEST(SnapshotVtk, RotationAngleOfTheRelativeRotation) {
  const Vec3 axis = Vec3(1, -2, 0.5).normalized();
  const Quat ref(Eigen::AngleAxisd(1.1, Vec3(0, 1, 1).normalized()));
  for (const double angle : {0.0, 0.3, 2.0, 3.1}) {
    const Quat now = Quat(Eigen::AngleAxisd(angle, axis)) * ref;
    EXPECT_NEAR(snapshot_rotation_angle(now, ref), angle, 1e-12) << angle;
    EXPECT_NEAR(snapshot_rotation_angle(Quat(-now.coeffs()), ref), angle, 1e-12) << "-q, " << angle;
  }
}

TEST(SnapshotVtk, TinyWorldSnapshotsRoundTrip) {
  World w = tiny_world();
  const Model& model = w.model;
  const std::size_t n = model.bodies.size();

  // The world has what the test needs: two grain-grain contacts, and both spheres on the floor.
  std::set<std::pair<Index, Index>> touching;
  for (const Contact& pc : w.state.contacts)
    if (in_contact(pc)) touching.insert({pc.a, pc.b});
  ASSERT_EQ(touching, (std::set<std::pair<Index, Index>>{{0, 1}, {0, 2}}));
  ASSERT_EQ(w.contact_count(), 4u);
  ASSERT_GT(w.state.walls[0].force.norm(), 0);

  // A reference where grain 1 sat d lower-left and grain 3 was turned by 0.4 rad.
  State ref = w.state;
  const Vec3 d(1e-4, -2e-4, 3e-4);
  ref.bodies[1].x -= d;
  ref.bodies[3].q = Quat(Eigen::AngleAxisd(-0.4, Vec3(0, 0, 1))) * w.state.bodies[3].q;

  test::IoTempDir dir;
  SnapshotWriter writer(dir.path / "run");
  const double t0 = w.state.time;
  writer.write(0, t0, model, w.state, &ref);

  // grains_0000.vtp
  const PolyData grains = read_vtp(dir.path / "run" / "grains_0000.vtp");
  std::size_t vertices = 0, faces = 0;
  for (std::size_t i = 0; i < n; ++i) {
    vertices += vertex_count(model, static_cast<Index>(i));
    faces += face_count(model, static_cast<Index>(i));
  }
  EXPECT_EQ(grains.point_count(), vertices);
  EXPECT_EQ(grains.polys.size(), faces);
  EXPECT_EQ(grains.lines.size() + grains.verts.size(), 0u);
  const auto& id = values<std::int32_t>(grains.point_data, "grain_id");
  const auto& disp = values<double>(grains.point_data, "displacement");
  const auto& rot = values<double>(grains.point_data, "rotation");
  const auto& vel = values<double>(grains.point_data, "velocity");
  const auto& cn = values<std::int32_t>(grains.point_data, "coordination");
  ASSERT_EQ(id.size(), vertices);
  ASSERT_EQ(disp.size(), 3 * vertices);
  ASSERT_EQ(rot.size(), vertices);
  ASSERT_EQ(vel.size(), 3 * vertices);
  ASSERT_EQ(cn.size(), vertices);
  const std::int32_t expected_cn[] = {2, 1, 1, 0};
  std::vector<std::size_t> points_of(n, 0);
  for (std::size_t p = 0; p < vertices; ++p) {
    ASSERT_GE(id[p], 0);
    ASSERT_LT(id[p], static_cast<std::int32_t>(n));
    const std::size_t g = static_cast<std::size_t>(id[p]);
    ++points_of[g];
    const BodyState& b = w.state.bodies[g];
    // Each point is on its grain's surface: within the scaled bounding radius of its centre.
    EXPECT_LE((point(grains, p) - b.x).norm(), model.bodies[g].bounding_radius * (1 + 1e-12));
    const Vec3 want_disp = g == 1 ? d : Vec3::Zero();
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(disp[3 * p + k], want_disp[k], 1e-15);
      EXPECT_EQ(vel[3 * p + k], b.v[k]);
    }
    EXPECT_NEAR(rot[p], g == 3 ? 0.4 : 0.0, 1e-12);
    EXPECT_EQ(cn[p], expected_cn[g]);
  }
  for (std::size_t g = 0; g < n; ++g) EXPECT_EQ(points_of[g], vertex_count(model, static_cast<Index>(g))) << g;
  // Grain ids come in blocks, grain after grain: grain 3's first point is its first mesh vertex at its pose.
  const std::size_t first3 = vertices - vertex_count(model, 3);
  const Vec3 want = w.state.bodies[3].x + w.state.bodies[3].q * (0.5 * model.shapes[1].mesh.vertices[0]);
  EXPECT_LT((point(grains, first3) - want).norm(), 1e-15);
  // Sphere grains are drawn on their radius.
  EXPECT_NEAR((point(grains, 0) - w.state.bodies[0].x).norm(), 1e-3, 1e-15);

  // contacts_0000.vtp: one line per grain-grain contact, between the centres, with the contact's force.
  const PolyData contacts = read_vtp(dir.path / "run" / "contacts_0000.vtp");
  ASSERT_EQ(contacts.lines.size(), touching.size());
  EXPECT_EQ(contacts.polys.size() + contacts.verts.size(), 0u);
  const auto& ga = values<std::int32_t>(contacts.cell_data, "grain_a");
  const auto& gb = values<std::int32_t>(contacts.cell_data, "grain_b");
  const auto& fmag = values<double>(contacts.cell_data, "force_magnitude");
  const auto& fn = values<double>(contacts.cell_data, "normal_force");
  const auto& ft = values<double>(contacts.cell_data, "tangential_force");
  const auto& normal = values<double>(contacts.cell_data, "normal");
  const auto& force = values<double>(contacts.cell_data, "force");
  ASSERT_EQ(force.size(), 3 * touching.size());
  std::size_t c = 0;
  for (const Contact& pc : w.state.contacts) {
    if (!in_contact(pc)) continue;
    EXPECT_EQ(ga[c], pc.a);
    EXPECT_EQ(gb[c], pc.b);
    const auto& conn = contacts.lines.connectivity;
    EXPECT_EQ(point(contacts, conn[2 * c]), w.state.bodies[pc.a].x);
    EXPECT_EQ(point(contacts, conn[2 * c + 1]), w.state.bodies[pc.b].x);
    EXPECT_EQ(Vec3(force[3 * c], force[3 * c + 1], force[3 * c + 2]), pc.force);
    const Vec3 nrm(normal[3 * c], normal[3 * c + 1], normal[3 * c + 2]);
    EXPECT_NEAR(nrm.norm(), 1, 1e-12);
    EXPECT_GT(nrm.dot(w.state.bodies[pc.b].x - w.state.bodies[pc.a].x), 0);  // from a to b
    EXPECT_EQ(fn[c], pc.normal_force);
    EXPECT_GT(fn[c], 0);  // pressed together
    EXPECT_EQ(fmag[c], pc.force.norm());
    EXPECT_NEAR(fmag[c] * fmag[c], fn[c] * fn[c] + ft[c] * ft[c], 1e-9 * fmag[c] * fmag[c]);
    ++c;
  }

  // walls_0000.vtp: the plane as 2 triangles, the box as 12, each carrying its id and force.
  const PolyData walls = read_vtp(dir.path / "run" / "walls_0000.vtp");
  EXPECT_EQ(walls.point_count(), 4u + 8u);
  ASSERT_EQ(walls.polys.size(), 2u + 12u);
  const auto& wid = values<std::int32_t>(walls.cell_data, "wall_id");
  const auto& wforce = values<double>(walls.cell_data, "force");
  ASSERT_EQ(wid.size(), 14u);
  for (std::size_t k = 0; k < 14; ++k) {
    const std::size_t wall = k < 2 ? 0 : 1;
    EXPECT_EQ(wid[k], static_cast<std::int32_t>(wall));
    EXPECT_EQ(Vec3(wforce[3 * k], wforce[3 * k + 1], wforce[3 * k + 2]), w.state.walls[wall].force);
  }
  for (std::size_t p = 0; p < 4; ++p) EXPECT_NEAR(point(walls, p).z(), 0, 1e-18);  // the floor patch lies in z = 0
  for (std::size_t p = 4; p < 12; ++p) {
    const Vec3 local = w.state.walls[1].q.conjugate() * (point(walls, p) - w.state.walls[1].x);
    EXPECT_NEAR(local.cwiseAbs().x(), 5e-3, 1e-15);
    EXPECT_NEAR(local.cwiseAbs().y(), 4e-3, 1e-15);
    EXPECT_NEAR(local.cwiseAbs().z(), 1e-3, 1e-15);
  }

  // A second snapshot later in the run: the collections list both, with their times.
  w.step(0.1 * w.critical_time_step());
  const double t1 = w.state.time;
  ASSERT_GT(t1, t0);
  writer.write(1, t1, model, w.state, &ref);
  for (const char* kind : {"grains", "contacts", "walls"}) {
    const std::vector<PvdEntry> entries = read_pvd(dir.path / "run" / (std::string(kind) + ".pvd"));
    ASSERT_EQ(entries.size(), 2u) << kind;
    EXPECT_EQ(entries[0], (PvdEntry{t0, SnapshotWriter::file_name(kind, 0)}));
    EXPECT_EQ(entries[1], (PvdEntry{t1, SnapshotWriter::file_name(kind, 1)}));
    for (const PvdEntry& e : entries) EXPECT_NO_THROW(read_vtp(dir.path / "run" / e.file)) << e.file;
  }
  EXPECT_EQ(writer.grains().entries().size(), 2u);
  EXPECT_EQ(SnapshotWriter::file_name("grains", 12345), "grains_12345.vtp");
}

TEST(SnapshotVtk, FirstSnapshotIsTheDefaultReference) {
  World w = tiny_world();
  test::IoTempDir dir;
  SnapshotWriter writer(dir.path);
  writer.write(0, 0.0, w.model, w.state);
  const State first = w.state;
  for (int k = 0; k < 20; ++k) w.step(0.1 * w.critical_time_step());
  writer.write(1, 1.0, w.model, w.state);
  const auto disp0 = values<double>(read_vtp(dir.path / "grains_0000.vtp").point_data, "displacement");
  const PolyData g1 = read_vtp(dir.path / "grains_0001.vtp");
  const auto& disp1 = values<double>(g1.point_data, "displacement");
  const auto& id = values<std::int32_t>(g1.point_data, "grain_id");
  for (double v : disp0) EXPECT_EQ(v, 0.0);
  double largest = 0;
  for (std::size_t p = 0; p < id.size(); ++p) {
    const Vec3 moved = w.state.bodies[id[p]].x - first.bodies[id[p]].x;
    for (int k = 0; k < 3; ++k) EXPECT_EQ(disp1[3 * p + k], moved[k]);
    largest = std::max(largest, moved.norm());
  }
  EXPECT_GT(largest, 0);  // the grains did move, so the check above could fail
}

TEST(SnapshotVtk, CallerFieldsAndOptions) {
  World w = tiny_world();
  const std::size_t n = w.model.bodies.size();
  GrainFields f = grain_fields(w.state, nullptr);
  EXPECT_TRUE(f.displacement.empty());
  EXPECT_EQ(f.coordination, (std::vector<std::int32_t>{2, 1, 1, 0}));
  f.extra.push_back({"in_band", 1, std::vector<std::int32_t>{1, 0, 1, 0}});
  f.extra.push_back({"stress", 2, std::vector<double>{1, 2, 3, 4, 5, 6, 7, 8}});
  SnapshotOptions opt;
  opt.single_precision = true;
  opt.sphere_subdivisions = 1;
  const PolyData pd = grains_polydata(w.model, w.state, f, opt);
  EXPECT_EQ(pd.points.values.index(), 1u);  // Float32
  std::size_t vertices = 0;
  for (std::size_t i = 0; i < n; ++i) vertices += vertex_count(w.model, static_cast<Index>(i), 1);
  EXPECT_EQ(pd.point_count(), vertices);
  const auto& id = values<std::int32_t>(pd.point_data, "grain_id");
  const auto& band = values<std::int32_t>(pd.point_data, "in_band");
  const auto& stress = values<float>(pd.point_data, "stress");
  ASSERT_EQ(stress.size(), 2 * vertices);
  for (std::size_t p = 0; p < vertices; ++p) {
    EXPECT_EQ(band[p], id[p] % 2 == 0 ? 1 : 0);
    EXPECT_EQ(stress[2 * p + 1], 2.0f * id[p] + 2);
  }
  for (const VtkArray& a : pd.point_data) EXPECT_NE(a.name, "displacement") << "no reference, no displacement";
  EXPECT_EQ(pd.point_data.size(), 5u);  // grain_id, velocity, coordination, in_band, stress: no rotation either

  f.velocity.pop_back();  // one short
  EXPECT_THROW(grains_polydata(w.model, w.state, f), std::invalid_argument);

  // A given plane size draws the floor as a square of that side.
  opt.plane_size = 0.25;
  const PolyData walls = walls_polydata(w.model, w.state, opt);
  EXPECT_NEAR((point(walls, 0) - point(walls, 2)).norm(), 0.25 * std::sqrt(2.0), 1e-15);
}

TEST(SnapshotVtk, SnapshotFilesAreWellFormedXmlPerXmllint) {
  if (!test::have_xmllint()) GTEST_SKIP() << "xmllint is not installed";
  World w = tiny_world();
  test::IoTempDir dir;
  SnapshotWriter writer(dir.path);
  writer.write(3, 0.5, w.model, w.state);
  for (const char* f : {"grains.pvd", "contacts.pvd", "walls.pvd"}) EXPECT_EQ(test::xmllint_status(dir.path / f), 0) << f;
  // The .vtp files are XML up to their raw (compressed) appended data.
  for (const char* f : {"grains_0003.vtp", "contacts_0003.vtp", "walls_0003.vtp"}) {
    const std::string text = test::file_text(dir.path / f);
    const std::size_t at = text.find("<AppendedData encoding=\"raw\">");
    ASSERT_NE(at, std::string::npos) << f;
    write_file_atomically(dir.path / "head.xml", text.substr(0, at) + "</VTKFile>\n");
    EXPECT_EQ(test::xmllint_status(dir.path / "head.xml"), 0) << f;
  }
}

// Bytes per grain face of a snapshot of 300 grains of `shape` in random
// poses, written inline (base64, Int64 cells: the files runs wrote before) and
// compressed (what runs write now), both with Float32 points and values.
std::pair<double, double> snapshot_bytes_per_face(bool spheres) {
  World w;
  const Index mat = w.model.add_material(Material{});
  const Index shape = spheres ? w.model.add_sphere_shape(0.4e-3, "bead")
                              : w.model.add_mesh_shape(icosphere(0.4e-3, 3), "faceted");  // 1280 faces
  std::uint64_t s = 12345;
  const auto uniform = [&s] {
    s = s * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<double>(s >> 11) * 0x1.0p-53;
  };
  for (int i = 0; i < 300; ++i)
    w.add_body(shape, mat, 1.0, Vec3(uniform(), uniform(), uniform()) * 8e-3,
               Quat(Eigen::AngleAxisd(6 * uniform(), Vec3(uniform(), uniform(), 1).normalized())));
  State reference = w.state;  // each grain moved and turned a little since
  for (std::size_t i = 0; i < reference.bodies.size(); ++i) {
    w.state.bodies[i].v = Vec3(uniform(), uniform(), uniform()) * 1e-3;
    reference.bodies[i].x += Vec3(uniform(), uniform(), uniform()) * 1e-4;
    reference.bodies[i].q = Quat(Eigen::AngleAxisd(0.1 * uniform(), Vec3::UnitX())) * reference.bodies[i].q;
  }
  SnapshotOptions opt;
  opt.single_precision = true;
  const PolyData pd = grains_polydata(w.model, w.state, grain_fields(w.state, &reference), opt);
  const double faces = static_cast<double>(pd.polys.size());
  return {static_cast<double>(vtp_text(pd, VtpEncoding::Inline).size()) / faces,
          static_cast<double>(vtp_text(pd).size()) / faces};
}

// Compressed snapshots are at least 5x smaller per grain face. Measured:
// spheres 75.1 -> 10.5 bytes per face (7.2x); 1280-face grains 74.8 -> 10.7 (7.0x).
TEST(SnapshotVtk, CompressedSnapshotsAreFiveTimesSmaller) {
  for (const bool spheres : {true, false}) {
    const auto [before, after] = snapshot_bytes_per_face(spheres);
    RecordProperty(spheres ? "sphere_bytes_per_face" : "faceted_bytes_per_face",
                   fmt::format("{:.1f} -> {:.1f}", before, after));
    EXPECT_GE(before / after, 5.0) << (spheres ? "spheres: " : "faceted: ") << before << " vs " << after
                                   << " bytes per face";
  }
}

}  // namespace
}  // namespace grainlab
