// grainlab's PLY reader: one mesh in the three formats, random meshes written
// with random scalar types and read back exactly, polygons cut without folds,
// and the refusals of counts and values the file cannot hold.
#include "geometry/ply_reader.h"

#include "geometry/mass_properties.h"
#include "geometry/mesh_io.h"
#include "test_helpers.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <random>
#include <string>
#include <vector>

namespace grainlab {
namespace {

enum class Format { ascii, little, big };

// The scalar types in PLY's order, each with its two header names and size.
struct Type {
  const char* name;
  const char* alias;
  int size;
  bool floating;
  double low, high;  // range of an integer type
};
constexpr Type kTypes[] = {
    {"char", "int8", 1, false, -128, 127},          {"uchar", "uint8", 1, false, 0, 255},
    {"short", "int16", 2, false, -32768, 32767},    {"ushort", "uint16", 2, false, 0, 65535},
    {"int", "int32", 4, false, -2147483648.0, 2147483647.0}, {"uint", "uint32", 4, false, 0, 4294967295.0},
    {"float", "float32", 4, true, 0, 0},            {"double", "float64", 8, true, 0, 0}};
enum TypeIndex { kChar, kUchar, kShort, kUshort, kInt, kUint, kFloat, kDouble };

// A small PLY writer: the header as given, values appended record by record.
class PlyWriter {
 public:
  explicit PlyWriter(Format f) : format_(f) {}

  std::string header_start() const {
    const char* name = format_ == Format::ascii    ? "ascii"
                       : format_ == Format::little ? "binary_little_endian"
                                                   : "binary_big_endian";
    return std::string("ply\nformat ") + name + " 1.0\ncomment written by ply_reader_test\n";
  }

  void value(int type, double v) {
    const Type& t = kTypes[type];
    if (format_ == Format::ascii) {
      body_ += t.floating ? (type == kFloat ? fmt::format("{} ", static_cast<float>(v)) : fmt::format("{} ", v))
                          : fmt::format("{} ", static_cast<long long>(v));
      return;
    }
    unsigned char b[8];
    switch (type) {
      case kChar: put<std::int8_t>(b, v); break;
      case kUchar: put<std::uint8_t>(b, v); break;
      case kShort: put<std::int16_t>(b, v); break;
      case kUshort: put<std::uint16_t>(b, v); break;
      case kInt: put<std::int32_t>(b, v); break;
      case kUint: put<std::uint32_t>(b, v); break;
      case kFloat: put<float>(b, v); break;
      default: put<double>(b, v); break;
    }
    for (int i = 0; i < t.size && i < 8; ++i)
      body_ += static_cast<char>(b[format_ == Format::big ? t.size - 1 - i : i]);  // big-endian: bytes reversed
  }

  void end_record() {
    if (format_ == Format::ascii) body_ += '\n';
  }

  const std::string& body() const { return body_; }

 private:
  template <typename T>
  static void put(unsigned char* b, double v) {
    const T x = static_cast<T>(v);
    std::memcpy(b, &x, sizeof(T));
  }

  Format format_;
  std::string body_;
};

void write_file(const std::filesystem::path& p, const std::string& bytes) {
  std::ofstream(p, std::ios::binary) << bytes;
}

TriMesh read_file(const std::filesystem::path& p) { return read_ply(p, std::filesystem::file_size(p)); }

// A 2 x 3 x 4 box of quads, with normals, a colour, a list per vertex, and an
// element before and after the vertices, in `f`.
std::string box_ply(Format f) {
  const double corners[8][3] = {{0, 0, 0}, {2, 0, 0}, {0, 3, 0}, {2, 3, 0}, {0, 0, 4}, {2, 0, 4}, {0, 3, 4}, {2, 3, 4}};
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  PlyWriter w(f);
  std::string header = w.header_start() +
                       "element material 2\nproperty uchar red\nproperty list uint8 float32 weights\n"
                       "element vertex 8\nproperty float nx\nproperty double x\nproperty uchar red\n"
                       "property float32 y\nproperty int16 z\nproperty list uchar ushort tags\nproperty float ny\n"
                       "element face 6\nproperty uchar flags\nproperty list uchar int vertex_indices\n"
                       "element edge 1\nproperty int vertex1\nproperty int vertex2\nend_header\n";
  for (int m = 0; m < 2; ++m) {
    w.value(kUchar, 10 + m);
    w.value(kUchar, m + 1);
    for (int k = 0; k <= m; ++k) w.value(kFloat, 0.25 * k);
    w.end_record();
  }
  for (const auto& c : corners) {
    w.value(kFloat, -1);
    w.value(kDouble, c[0]);
    w.value(kUchar, 200);
    w.value(kFloat, c[1]);
    w.value(kShort, c[2]);
    w.value(kUchar, 2);
    w.value(kUshort, 7);
    w.value(kUshort, 65535);
    w.value(kFloat, 0.5);
    w.end_record();
  }
  for (const auto& q : quads) {
    w.value(kUchar, 1);
    w.value(kUchar, 4);
    for (const int i : q) w.value(kInt, i);
    w.end_record();
  }
  w.value(kInt, 0);
  w.value(kInt, 1);
  w.end_record();
  return header + w.body();
}

TEST(PlyReader, OneBoxInTheThreeFormatsReadsToOneMesh) {
  test::TempDir dir;
  std::vector<TriMesh> meshes;
  for (const Format f : {Format::ascii, Format::little, Format::big}) {
    const auto path = dir / ("box" + std::to_string(static_cast<int>(f)) + ".ply");
    write_file(path, box_ply(f));
    meshes.push_back(read_mesh(path));
  }
  ASSERT_EQ(meshes[0].vertices.size(), 8u);
  ASSERT_EQ(meshes[0].faces.size(), 12u);  // each quad cut in two
  EXPECT_NEAR(mass_properties(meshes[0]).volume, 2.0 * 3.0 * 4.0, 1e-12);
  for (int i = 1; i < 3; ++i) {
    EXPECT_EQ(meshes[i].vertices, meshes[0].vertices);
    EXPECT_EQ(meshes[i].faces, meshes[0].faces);
  }
}

// Random meshes written with random scalar types in a random format, with
// properties and elements grainlab skips, come back exactly: integers and
// doubles as written, floats as their single-precision value.
TEST(PlyReader, RandomMeshesRoundTripInEveryFormatAndScalarType) {
  test::TempDir dir;
  std::mt19937_64 rng(20261207);
  const auto uniform = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
  const auto pick = [&](int n) { return static_cast<int>(rng() % static_cast<unsigned>(n)); };
  for (int trial = 0; trial < 150; ++trial) {
    const auto format = static_cast<Format>(pick(3));
    const int nv = 3 + pick(60), nf = 1 + pick(40);
    const int xyz_type[3] = {pick(8), pick(8), pick(8)};
    // Item types that can hold the indices (char holds up to 127), any count type.
    const int count_type = pick(6), item_type = nv <= 127 ? pick(6) : 2 + pick(4);
    const int extra = pick(8);  // a skipped scalar property's type
    const auto name = [&](int t) { return pick(2) ? kTypes[t].name : kTypes[t].alias; };
    std::string header;
    PlyWriter w(format);
    header = w.header_start();
    if (pick(2)) {
      header += fmt::format("element extra 1\nproperty list {} {} values\n", name(kUchar), name(extra));
      w.value(kUchar, 2);
      w.value(extra, 1);
      w.value(extra, 0);
      w.end_record();
    }
    header += fmt::format("element vertex {}\nproperty {} x\nproperty {} nx\nproperty {} y\nproperty {} z\n", nv,
                          name(xyz_type[0]), name(extra), name(xyz_type[1]), name(xyz_type[2]));
    header += fmt::format("element face {}\nproperty list {} {} vertex_indices\nend_header\n", nf, name(count_type),
                          name(item_type));
    TriMesh expected;
    for (int v = 0; v < nv; ++v) {
      Vec3 p;
      for (int k = 0; k < 3; ++k) {
        const Type& t = kTypes[xyz_type[k]];
        p[k] = !t.floating             ? std::round(uniform(t.low, t.high))
               : xyz_type[k] == kFloat ? static_cast<float>(uniform(-1e3, 1e3))
                                       : uniform(-1e3, 1e3) * std::pow(10.0, pick(40) - 20);
      }
      w.value(xyz_type[0], p.x());
      w.value(extra, 1);
      w.value(xyz_type[1], p.y());
      w.value(xyz_type[2], p.z());
      w.end_record();
      expected.vertices.push_back(p);
    }
    for (int f = 0; f < nf; ++f) {
      const Face face = {pick(nv), pick(nv), pick(nv)};
      w.value(count_type, 3);
      for (const Index i : face) w.value(item_type, i);
      w.end_record();
      expected.faces.push_back(face);
    }
    const auto path = dir / "random.ply";
    write_file(path, header + w.body());
    const TriMesh r = read_file(path);
    ASSERT_EQ(r.vertices, expected.vertices) << "trial " << trial << "\n" << header;
    ASSERT_EQ(r.faces, expected.faces) << "trial " << trial << "\n" << header;
  }
}

// A polygon becomes a fan from the first corner whose triangles all face the
// polygon's way: a concave quad (a dart) is cut along its inner diagonal, so
// the triangles' areas add up to the quad's, none folded over.
TEST(PlyReader, ConcavePolygonIsCutWithoutAFold) {
  test::TempDir dir;
  // The dart (0,0) (4,0) (1,1) (0,4), its reflex corner the third: area 4.
  for (const std::string order : {"0 1 2 3", "1 2 3 0", "2 3 0 1", "3 0 1 2"}) {
    write_file(dir / "dart.ply", "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                                 "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                                 "end_header\n0 0 0\n4 0 0\n1 1 0\n0 4 0\n4 " + order + "\n");
    const TriMesh m = read_file(dir / "dart.ply");
    ASSERT_EQ(m.faces.size(), 2u);
    double area = 0;
    for (const Face& f : m.faces) {
      const double z = (m.vertices[f[1]] - m.vertices[f[0]]).cross(m.vertices[f[2]] - m.vertices[f[0]]).z() / 2;
      EXPECT_GE(z, 0) << order;
      area += z;
    }
    EXPECT_DOUBLE_EQ(area, 4.0) << order;
  }
}

// A binary list whose count needs more bytes than the file has left is refused
// from the count, before its items are read or anything is reserved for them
// (4e9 four-byte items would be 16 GB).
TEST(PlyReader, BinaryListCountLargerThanTheFileIsRefusedBeforeAllocation) {
  test::TempDir dir;
  const std::string header = "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
                             "property float y\nproperty float z\nelement face 1\n"
                             "property list uint int vertex_indices\nend_header\n";
  std::string body(36, '\0');
  const std::uint32_t count = 4000000000u;
  body.append(reinterpret_cast<const char*>(&count), 4);
  body.append(12, '\0');
  write_file(dir / "count.ply", header + body);
  EXPECT_CONTAINS(test::input_error_of([&] { read_file(dir / "count.ply"); }),
                  "face 1 starts a list with the count 4000000000 at byte " + std::to_string(header.size() + 36) +
                      ", whose 4-byte items take more than the 12 bytes left in the file");
  // The same in an element grainlab skips, and a count that is no whole number.
  std::string skipped = header;
  skipped.replace(skipped.find("element face"), 0, "element extra 1\nproperty list int uchar tags\n");
  const std::int32_t negative = -3;
  write_file(dir / "negative.ply", skipped + std::string(36, '\0') +
                                       std::string(reinterpret_cast<const char*>(&negative), 4) + body.substr(36));
  EXPECT_CONTAINS(test::input_error_of([&] { read_file(dir / "negative.ply"); }),
                  "extra 1 starts a list with the count -3 at byte " + std::to_string(skipped.size() + 36) +
                      ", not a whole number");
  // Data ending inside a record: two faces announced (44 bytes at least), the
  // first's items fill the file.
  std::string two = header;
  two.replace(two.find("face 1"), 6, "face 2");
  write_file(dir / "short.ply", two + std::string(36, '\0') + std::string("\3\0\0\0", 4) + std::string(12, '\0'));
  EXPECT_CONTAINS(test::input_error_of([&] { read_file(dir / "short.ply"); }),
                  "its binary PLY data ends inside face 2 of the 2 its header announces (at byte " +
                      std::to_string(two.size() + 52) + ")");
}

// What the reader refuses that no bound catches: faces of fewer than 3
// corners, indices out of range, values that are not numbers of their type,
// a header without format or without a vertex's x, y or z.
TEST(PlyReader, MalformedFacesValuesAndHeadersAreRefused) {
  test::TempDir dir;
  const std::string head = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                           "property uchar z\nelement face 1\nproperty list uchar int vertex_index\nend_header\n";
  const std::string vertices = "0 0 0\n1 0 0\n0 1 0\n";
  const auto refusal = [&](const std::string& text) {
    write_file(dir / "bad.ply", text);
    return test::input_error_of([&] { read_file(dir / "bad.ply"); });
  };
  write_file(dir / "ok.ply", head + vertices + "3 0 1 2\n");
  EXPECT_EQ(read_file(dir / "ok.ply").faces.size(), 1u);
  EXPECT_CONTAINS(refusal(head + vertices + "2 0 1\n"),
                  "face 1 has 2 vertices (its list at byte " + std::to_string(head.size() + 18) +
                      "), where a face needs at least 3");
  EXPECT_CONTAINS(refusal(head + vertices + "3 0 -1 2\n"), "face 1 names vertex -1, but the mesh has 3 vertices");
  EXPECT_CONTAINS(refusal(head + vertices + "3 0 3 2\n"), "face 1 names vertex 3, but the mesh has 3 vertices");
  EXPECT_CONTAINS(refusal(head + "0 0 0\n1 0x 0\n0 1 0\n3 0 1 2\n"),
                  "vertex 2 holds '0x' at byte " + std::to_string(head.size() + 8) +
                      ", which is not a number of its type (float)");
  EXPECT_CONTAINS(refusal(head + "0 0 0\n1 0 256\n0 1 0\n3 0 1 2\n"),
                  "vertex 2 holds '256' at byte " + std::to_string(head.size() + 10) +
                      ", which is not a number of its type (uchar)");
  std::string no_format = head;
  no_format.erase(4, 17);
  EXPECT_CONTAINS(refusal(no_format + vertices + "3 0 1 2\n"), "its PLY header has no 'format' line");
  std::string no_z = head;
  no_z.replace(no_z.find("uchar z"), 7, "uchar w");
  EXPECT_CONTAINS(refusal(no_z + vertices + "3 0 1 2\n"), "gives the element 'vertex' no scalar property 'z'");
  std::string no_list = head;
  no_list.replace(no_list.find("vertex_index"), 12, "corners");
  EXPECT_CONTAINS(refusal(no_list + vertices + "3 0 1 2\n"), "gives the element 'face' no list 'vertex_indices'");
}

}  // namespace
}  // namespace grainlab
