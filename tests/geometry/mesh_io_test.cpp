// Mesh files: round trips, hand-written files, and refused files.
#include "geometry/mesh_io.h"

#include "geometry/mass_properties.h"
#include "geometry/primitives.h"
#include "test_helpers.h"

#include <gtest/gtest.h>

#include <array>
#include <fstream>

namespace grainlab {
namespace {

const std::filesystem::path kMeshes = std::filesystem::path(GRAINLAB_TEST_DATA) / "meshes";

// An icosphere with coordinates already in single precision, as files store them.
TriMesh float_icosphere() {
  TriMesh m = icosphere(0.8e-3, 3);
  // Through a volatile float: GCC 12.2's SLP vectoriser (-O2 and up) drops a
  // double -> float -> double round trip done in registers on adjacent elements.
  for (Vec3& v : m.vertices) {
    for (int k = 0; k < 3; ++k) {
      volatile float f = static_cast<float>(v[k]);
      v[k] = f;
    }
  }
  return m;
}

// An icosphere of radius 1000 with integer coordinates: exact in any text format
// and in single precision (assimp's text parsers can be 1 float ulp off otherwise).
TriMesh integer_icosphere() {
  TriMesh m = icosphere(1000.0, 3);
  for (Vec3& v : m.vertices) v = v.array().round().matrix();
  return m;
}

void write_text(const std::filesystem::path& p, const std::string& text) {
  std::ofstream(p, std::ios::binary) << text;
}

TEST(MeshIo, BinaryStlRoundTrip) {
  test::TempDir dir;
  const TriMesh m = float_icosphere();
  write_stl(m, dir / "sphere.stl");
  const TriMesh r = read_mesh(dir / "sphere.stl");
  EXPECT_EQ(r.vertices.size(), m.vertices.size());
  EXPECT_EQ(r.faces.size(), m.faces.size());
  EXPECT_NEAR(mass_properties(r).volume / mass_properties(m).volume, 1.0, 1e-12);
  EXPECT_EQ(std::filesystem::file_size(dir / "sphere.stl"), 84 + 50 * m.faces.size());
  // Only the final file is left: the temporary was renamed.
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path), {}), 1);
}

TEST(MeshIo, ObjRoundTrip) {
  test::TempDir dir;
  const TriMesh m = integer_icosphere();
  write_obj(m, dir / "sphere.obj");
  const TriMesh r = read_mesh(dir / "sphere.obj");
  EXPECT_EQ(r.vertices.size(), m.vertices.size());
  EXPECT_EQ(r.faces.size(), m.faces.size());
  EXPECT_NEAR(mass_properties(r).volume / mass_properties(m).volume, 1.0, 1e-12);
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path), {}), 1);
  // Arbitrary doubles come back to single precision.
  const TriMesh g = icosphere(0.8e-3, 3);
  write_obj(g, dir / "sphere.obj");  // overwrites through the temporary
  const TriMesh rg = read_mesh(dir / "sphere.obj");
  EXPECT_EQ(rg.vertices.size(), g.vertices.size());
  EXPECT_NEAR(mass_properties(rg).volume / mass_properties(g).volume, 1.0, 1e-6);
}

TEST(MeshIo, HandWrittenAsciiStl) {
  const TriMesh m = read_mesh(kMeshes / "tetra_ascii.stl");
  EXPECT_EQ(m.vertices.size(), 4u);  // 12 corners merged to 4
  EXPECT_EQ(m.faces.size(), 4u);
  EXPECT_NEAR(mass_properties(m).volume, 1.0 / 6.0, 1e-15);
}

TEST(MeshIo, HandWrittenPlyWithQuads) {
  const TriMesh m = read_mesh(kMeshes / "cube_quads.ply");
  EXPECT_EQ(m.vertices.size(), 8u);
  EXPECT_EQ(m.faces.size(), 12u);  // quads triangulated
  const MassProperties mp = mass_properties(m);
  EXPECT_NEAR(mp.volume, 1.0, 1e-15);
  EXPECT_NEAR((mp.centroid - Vec3::Constant(0.5)).norm(), 0.0, 1e-15);
}

TEST(MeshIo, AsciiStlWrittenInTheTest) {
  test::TempDir dir;
  // An upper-case extension is accepted.
  write_text(dir / "TRI.STL",
             "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
             "endloop\nendfacet\nendsolid t\n");
  const TriMesh m = read_mesh(dir / "TRI.STL");
  EXPECT_EQ(m.vertices.size(), 3u);
  EXPECT_EQ(m.faces.size(), 1u);
  // assimp rejects whitespace before "solid"; the message says what to delete.
  write_text(dir / "blank.stl",
             "\n  solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
             "endloop\nendfacet\nendsolid t\n");
  const std::string msg = test::input_error_of([&] { read_mesh(dir / "blank.stl"); });
  EXPECT_CONTAINS(msg, "blank.stl");
  EXPECT_CONTAINS(msg, "3 blank character(s) before 'solid'");
}

TEST(MeshIo, MissingFile) {
  const std::string msg = test::input_error_of([] { read_mesh("/nonexistent/grain.stl"); });
  EXPECT_CONTAINS(msg, "'/nonexistent/grain.stl'");
  EXPECT_CONTAINS(msg, "file not found");
}

TEST(MeshIo, UnsupportedExtension) {
  test::TempDir dir;
  write_text(dir / "grain.xyz", "0 0 0\n");
  const std::string msg = test::input_error_of([&] { read_mesh(dir / "grain.xyz"); });
  EXPECT_CONTAINS(msg, "grain.xyz");
  EXPECT_CONTAINS(msg, "unsupported file type '.xyz'");
  EXPECT_CONTAINS(msg, "STL, OBJ or PLY");
}

TEST(MeshIo, EmptyFiles) {
  test::TempDir dir;
  for (const char* name : {"empty.stl", "empty.obj", "empty.ply"}) {
    write_text(dir / name, "");
    const std::string msg = test::input_error_of([&] { read_mesh(dir / name); });
    EXPECT_CONTAINS(msg, name);
    EXPECT_CONTAINS(msg, "empty");
  }
  // An OBJ with vertices but no faces is an empty mesh too.
  write_text(dir / "points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n");
  const std::string msg = test::input_error_of([&] { read_mesh(dir / "points.obj"); });
  EXPECT_CONTAINS(msg, "points.obj");
  EXPECT_CONTAINS(msg, "no triangles");
}

TEST(MeshIo, TruncatedBinaryStl) {
  test::TempDir dir;
  const TriMesh m = float_icosphere();  // 1280 triangles
  const auto path = dir / "grain.stl";
  write_stl(m, path);
  std::filesystem::resize_file(path, 84 + 50 * 1000 + 17);
  const std::string msg = test::input_error_of([&] { read_mesh(path); });
  EXPECT_CONTAINS(msg, "grain.stl");
  EXPECT_CONTAINS(msg, "binary STL is truncated (header says 1280 triangles, file holds 1000)");
  EXPECT_CONTAINS(msg, "re-export");
  std::filesystem::resize_file(path, 40);
  EXPECT_CONTAINS(test::input_error_of([&] { read_mesh(path); }), "too short for a binary STL");
}

TEST(MeshIo, NonFiniteCoordinates) {
  test::TempDir dir;
  write_text(dir / "nan.obj", "v 0 0 0\nv 1 0 0\nv 0 nan 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 4 3\n");
  const std::string msg = test::input_error_of([&] { read_mesh(dir / "nan.obj"); });
  EXPECT_CONTAINS(msg, "nan.obj");
  EXPECT_CONTAINS(msg, "1 vertex has non-finite");
}

TEST(MeshIo, GarbageRefused) {
  test::TempDir dir;
  write_text(dir / "junk.ply", "this is not a ply file\n");
  const std::string msg = test::input_error_of([&] { read_mesh(dir / "junk.ply"); });
  EXPECT_CONTAINS(msg, "mesh '" + (dir / "junk.ply").string() + "': its first line is 'this is not a ply file', where "
                       "a PLY file starts with the line 'ply'");
}

// A PLY header may announce any count; assimp reserved memory for it (a
// 1 kB file claiming 1e8 vertices took 1.2 GB). The counts are checked
// against the bytes after the header first, ASCII and binary.
TEST(MeshIo, PlyHeaderClaimingMoreThanTheFileHoldsIsRefused) {
  test::TempDir dir;
  const std::string tail = "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
  write_text(dir / "ascii.ply", "ply\nformat ascii 1.0\nelement vertex 100000000\nproperty float x\nproperty float y\n"
                                "property float z\n" + tail + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  std::string msg = test::input_error_of([&] { read_mesh(dir / "ascii.ply"); });
  EXPECT_CONTAINS(msg, "ascii.ply");
  EXPECT_CONTAINS(msg, "100000000 vertex");
  EXPECT_CONTAINS(msg, "re-export");
  // Binary: 3 floats a vertex, 12 bytes; 4 vertices and a face need at least 4 x 12 + 1 (its count byte).
  const std::string binary_header = "ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\n"
                                    "property float y\nproperty float z\n" + tail;
  write_text(dir / "binary.ply", binary_header + std::string(40, '\0'));
  msg = test::input_error_of([&] { read_mesh(dir / "binary.ply"); });
  EXPECT_CONTAINS(msg, "at least 49 bytes");
  EXPECT_CONTAINS(msg, "holds 40 bytes after its header");
  // Enough bytes, but the face has no vertex: assimp's triangulation aborted the process on it.
  write_text(dir / "empty_face.ply", binary_header + std::string(49, '\0'));
  msg = test::input_error_of([&] { read_mesh(dir / "empty_face.ply"); });
  EXPECT_CONTAINS(msg, "face 1 has no vertex");
  // The same header with the bytes it announces is read (the bound refuses no real file).
  const float v[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  std::string ok(reinterpret_cast<const char*>(v), sizeof(v));
  const std::string faces = "ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\n"
                            "property float y\nproperty float z\nelement face 4\n"
                            "property list uchar int vertex_indices\nend_header\n";
  for (const std::array<int, 3>& f : {std::array{0, 2, 1}, std::array{0, 1, 3}, std::array{1, 2, 3}, std::array{0, 3, 2}}) {
    ok += '\3';
    ok.append(reinterpret_cast<const char*>(f.data()), 12);
  }
  write_text(dir / "tet.ply", faces + ok);
  EXPECT_EQ(read_mesh(dir / "tet.ply").faces.size(), 4u);
}

// A PLY header with no end_header, or a property of an unknown type, made
// assimp's binary reader read out of bounds (found by fuzzing:
// tests/fuzz/corpus/ply/crash_header_without_end_259f6ba0).
TEST(MeshIo, PlyHeaderWithoutItsEndOrWithAnUnknownPropertyTypeIsRefused) {
  test::TempDir dir;
  const std::string head = "ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\n";
  write_text(dir / "no_end.ply", head + "property float y\nproperty float z\n");
  std::string msg = test::input_error_of([&] { read_mesh(dir / "no_end.ply"); });
  EXPECT_CONTAINS(msg, "its PLY header has no 'end_header' line before the file's end");
  write_text(dir / "odd_type.ply", head + "property flaot y\nproperty float z\nend_header\n" + std::string(48, '\0'));
  msg = test::input_error_of([&] { read_mesh(dir / "odd_type.ply"); });
  EXPECT_CONTAINS(msg, "PLY header line 'property flaot y' is not 'property TYPE NAME'");
  write_text(dir / "list.ply", head + "element face 1\nproperty list uch\nend_header\n" + std::string(48, '\0'));
  msg = test::input_error_of([&] { read_mesh(dir / "list.ply"); });
  EXPECT_CONTAINS(msg, "PLY header line 'property list uch' is not");
}

// A PLY face naming a vertex past the mesh's (assimp's reader does not
// check) crashed the process in assimp's triangulation (found by fuzzing:
// tests/fuzz/corpus/ply/crash_face_index_past_vertices.ply).
TEST(MeshIo, PlyFaceNamingAVertexPastTheMeshIsRefused) {
  test::TempDir dir;
  const float v[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  std::string body(reinterpret_cast<const char*>(v), sizeof(v));
  body += '\3';
  const int f[3] = {0, 255, 1};
  body.append(reinterpret_cast<const char*>(f), sizeof(f));
  write_text(dir / "bad_index.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\n"
                                    "property float y\nproperty float z\nelement face 1\n"
                                    "property list uchar int vertex_indices\nend_header\n" + body);
  const std::string msg = test::input_error_of([&] { read_mesh(dir / "bad_index.ply"); });
  EXPECT_CONTAINS(msg, "face 1 names vertex 255, but the mesh has 4 vertices");
}

// A PLY header line of no keyword, or an unknown format, made assimp's
// reader loop for minutes (found by fuzzing): refused from the header.
TEST(MeshIo, PlyHeaderOfAnUnknownFormatOrKeywordIsRefused) {
  test::TempDir dir;
  const std::string rest = "element vertex 3\nproperty float x\nproperty float y\nproperty float z\nend_header\n"
                           "0 0 0\n1 0 0\n0 1 0\n";
  write_text(dir / "format.ply", "ply\nformat binary_little_endia 1.0\n" + rest);
  EXPECT_CONTAINS(test::input_error_of([&] { read_mesh(dir / "format.ply"); }),
                  "PLY format 'binary_little_endia' is none of ascii, binary_little_endian, binary_big_endian");
  write_text(dir / "keyword.ply", "ply\nformat ascii 1.0\nelemert vertex 3\n" + rest);
  EXPECT_CONTAINS(test::input_error_of([&] { read_mesh(dir / "keyword.ply"); }),
                  "PLY header line 'elemert vertex 3' starts with no PLY keyword");
}

// A PLY header holding a NUL (a binary first line "ply\0...") made assimp's
// reader wait on the file forever (found by fuzzing:
// tests/fuzz/corpus/ply/hang_nul_in_header_8182730c): refused at its byte.
TEST(MeshIo, PlyHeaderHoldingAControlCharacterOrNotStartingWithPlyIsRefused) {
  test::TempDir dir;
  const std::string rest = "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                           "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
                           "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  write_text(dir / "nul.ply", "ply" + std::string(2, '\0') + "\xdd\nformat ascii 1.0\n" + rest);
  EXPECT_CONTAINS(test::input_error_of([&] { read_mesh(dir / "nul.ply"); }),
                  "its PLY header holds a control character (byte 0x00) at byte 3");
  // A first line other than "ply" made assimp wait the same way
  // (tests/fuzz/corpus/ply/hang_first_line_plyply_ab1de0a2).
  write_text(dir / "plyply.ply", "plyply\nformat ascii 1.0\ncomment unit \nfocurbe ");
  EXPECT_CONTAINS(test::input_error_of([&] { read_mesh(dir / "plyply.ply"); }),
                  "its first line is 'plyply', where a PLY file starts with the line 'ply'");
  write_text(dir / "bell.ply", "ply\nformat ascii 1.0\ncomment unit \a mm\n" + rest);
  EXPECT_CONTAINS(test::input_error_of([&] { read_mesh(dir / "bell.ply"); }),
                  "control character (byte 0x07) at byte 34");
  // ASCII data is text too: a NUL in it made assimp wait the same way
  // (tests/fuzz/corpus/ply/hang_nul_in_ascii_data_80cc5b86).
  const std::string header = "ply\nformat ascii 1.0\n" + rest.substr(0, rest.find("0 0 0"));
  write_text(dir / "data.ply", header + "0 0 0\n1 0" + std::string(1, '\0') + " 0\n0 1 0\n3 0 1 2\n");
  EXPECT_CONTAINS(test::input_error_of([&] { read_mesh(dir / "data.ply"); }),
                  "its ASCII PLY data holds a control character (byte 0x00) at byte " +
                      std::to_string(header.size() + 9));
  // A list count of many digits made assimp reserve gigabytes
  // (tests/fuzz/corpus/ply/oom_list_count_554bc5ee, oom_list_count_7becb8e7):
  // each count is held to the values left on its line (a record a line).
  write_text(dir / "count.ply", header + "0 0 0\n1 0 0\n\n0 1 0\n4000000000 0 1 2\n");
  EXPECT_CONTAINS(test::input_error_of([&] { read_mesh(dir / "count.ply"); }),
                  "face 1 starts a list with the count '4000000000' at byte " + std::to_string(header.size() + 19) +
                      ", more than the 3 values left on its line");
  // Fewer records or values than announced made assimp take 20 GB in a
  // minute (tests/fuzz/corpus/ply/oom_records_missing_c735b2de).
  write_text(dir / "short.ply", header + "0.000000 0.000000 0.000000\n1.000000 0 0\n");
  EXPECT_CONTAINS(test::input_error_of([&] { read_mesh(dir / "short.ply"); }),
                  "its ASCII PLY data ends after 2 of the 3 vertex records its header announces");
  write_text(dir / "values.ply", header + "0 0 0\n1 0\n0 1 0\n3 0 1 2\n");
  EXPECT_CONTAINS(test::input_error_of([&] { read_mesh(dir / "values.ply"); }),
                  "vertex 2 (the line at byte " + std::to_string(header.size() + 6) +
                      ") holds fewer values than the 3 properties");
  // An end_header without its line end made assimp seek for ever
  // (tests/fuzz/corpus/ply/hang_end_header_at_eof_8d14cc83).
  write_text(dir / "end.ply", "ply\nformat ascii 1.0\nelement vertex 0\nend_header");
  EXPECT_CONTAINS(test::input_error_of([&] { read_mesh(dir / "end.ply"); }),
                  "its PLY header ends the file without a line end after 'end_header'");
  // An element name of digits made assimp ask for 80 GB
  // (tests/fuzz/corpus/ply/oom_element_name_digits_412762ba).
  write_text(dir / "digits.ply", "ply\nformat ascii 1.0\nelement 1111vertex 3\n" + rest.substr(17));
  EXPECT_CONTAINS(test::input_error_of([&] { read_mesh(dir / "digits.ply"); }),
                  "names an element '1111vertex', which does not start with a letter");
  // Two format lines (tests/fuzz/corpus/ply/oom_format_twice_5341442b).
  write_text(dir / "formats.ply", "ply\nformat ascii 1.0\nformat binary_little_endian 1.0\n" + rest);
  EXPECT_CONTAINS(test::input_error_of([&] { read_mesh(dir / "formats.ply"); }), "its PLY header gives 'format' twice");
  write_text(dir / "long.ply", header + "0 0 0\n1 0 0\n0 1 0\n3 0 1 " + std::string(70, '2') + "\n");
  EXPECT_CONTAINS(test::input_error_of([&] { read_mesh(dir / "long.ply"); }),
                  "holds a value of more than 64 characters at byte " + std::to_string(header.size() + 24));
  // An element or a property named twice corrupted assimp's memory
  // (tests/fuzz/corpus/ply/heap_corruption_element_twice_0148e63a).
  write_text(dir / "twice.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n" + rest);
  EXPECT_CONTAINS(test::input_error_of([&] { read_mesh(dir / "twice.ply"); }),
                  "its PLY header announces the element 'vertex' twice");
  std::string x_twice = rest;
  x_twice.replace(x_twice.find("property float y"), 16, "property float x");
  write_text(dir / "x_twice.ply", "ply\nformat ascii 1.0\n" + x_twice);
  EXPECT_CONTAINS(test::input_error_of([&] { read_mesh(dir / "x_twice.ply"); }),
                  "its PLY header gives element 'vertex' the property 'x' twice");
  // Tabs and CRLF line ends are text: the same file with them is read.
  write_text(dir / "crlf.ply", "ply\r\nformat ascii 1.0\r\ncomment\tunit mm\r\n" + rest);
  EXPECT_EQ(read_mesh(dir / "crlf.ply").faces.size(), 1u);
}

// A device or a pipe named like a mesh is refused before anything reads it.
TEST(MeshIo, NonRegularFileIsRefused) {
  test::TempDir dir;
  std::filesystem::create_symlink("/dev/zero", dir / "zero.stl");
  const std::string msg = test::input_error_of([&] { read_mesh(dir / "zero.stl"); });
  EXPECT_CONTAINS(msg, "zero.stl");
  EXPECT_CONTAINS(msg, "regular file");
}

TEST(MeshIo, UnwritablePath) {
  const std::string msg =
      test::input_error_of([] { write_stl(box_mesh(1, 1, 1), "/nonexistent/dir/out.stl"); });
  EXPECT_CONTAINS(msg, "cannot write '/nonexistent/dir/out.stl'");
}

}  // namespace
}  // namespace grainlab
