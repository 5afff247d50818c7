// Mesh files in and out. assimp parses the formats; grainlab checks what
// assimp is lenient about (a truncated binary STL, an empty file) and turns
// every failure into a message naming the file, the defect and a fix.
//
// Binary STL layout: 80-byte header, uint32 triangle count n (little
// endian), then n records of 50 bytes (normal and three vertices as 12
// float32, then a uint16 attribute), so a whole file is 84 + 50 n bytes.
// An ASCII STL starts with "solid"; a binary header may too, so the size
// test decides first.
//
// PLY: a text header ("element vertex N", "property float x", ...,
// "end_header") announces each element's count; assimp reserves memory for
// it before reading. Every element takes at least, per property, one byte
// (binary: the scalar's size; a list: its count's size) or two characters
// (ASCII: a digit and a separator), so counts whose total exceeds the bytes
// after the header are refused before assimp sees the file.
#include "core/text.h"
#include "geometry/mesh_io.h"

#include "core/atomic_file.h"
#include "core/bounded_line.h"
#include "core/bounded_read.h"
#include "core/error.h"

#include <assimp/Importer.hpp>
#include <assimp/config.h>
#include <assimp/mesh.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <unistd.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cctype>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <system_error>
#include <utility>

namespace grainlab {
namespace {

static_assert(std::endian::native == std::endian::little, "binary STL I/O assumes a little-endian host");

// Refuses a binary STL whose size does not hold the triangles its header announces.
void validate_stl(const std::filesystem::path& path, std::uintmax_t size) {
  const std::string name = path.string();
  std::ifstream in(path, std::ios::binary);
  char head[84] = {};
  in.read(head, static_cast<std::streamsize>(std::min<std::uintmax_t>(size, 84)));
  if (!in && !in.eof()) input_error("mesh '{}': cannot be read; check its permissions", name);
  std::size_t i = 0;
  while (i < size && i < 80 && std::isspace(static_cast<unsigned char>(head[i]))) ++i;
  const bool says_solid = size >= i + 5 && std::strncmp(head + i, "solid", 5) == 0;
  std::uint32_t n = 0;
  std::memcpy(&n, head + 80, 4);
  const std::uintmax_t expected = 84 + 50 * static_cast<std::uintmax_t>(n);
  if (size >= 84 && size == expected) return;  // a well-formed binary STL
  if (says_solid && i > 0) {
    input_error("mesh '{}': ASCII STL has {} blank character(s) before 'solid'; delete them so that "
                "the file starts with 'solid'",
                name, i);
  }
  if (says_solid) return;  // ASCII: assimp parses and checks it
  if (size >= 84) {
    if (size < expected) {
      input_error("mesh '{}': binary STL is truncated (header says {} triangles, file holds {}); "
                  "re-export the mesh",
                  name, n, (size - 84) / 50);
    }
    return;  // trailing bytes after the last triangle: some exporters pad
  }
  input_error("mesh '{}': too short for a binary STL ({} bytes; header and triangle count alone "
              "take 84) and not ASCII STL (no 'solid'); re-export the mesh",
              name, size);
}

// Bytes of one PLY scalar type, 0 if unknown.
std::uintmax_t ply_type_size(std::string_view t) {
  if (t == "char" || t == "uchar" || t == "int8" || t == "uint8") return 1;
  if (t == "short" || t == "ushort" || t == "int16" || t == "uint16") return 2;
  if (t == "int" || t == "uint" || t == "float" || t == "int32" || t == "uint32" || t == "float32") return 4;
  if (t == "double" || t == "float64") return 8;
  return 0;
}

// An element of a PLY header: its name and count, the least bytes one record
// takes, which of its properties are lists, and their names.
struct PlyElement {
  std::string name;
  std::uintmax_t count = 0, min_bytes = 0;
  std::vector<bool> lists;
  std::vector<std::string> properties;
};

// ASCII PLY data is text, one record a line: a NUL or another control
// character in it (a damaged or binary body) made assimp's reader wait on the
// file for ever, and a list count of many digits made it reserve gigabytes
// (both found by fuzzing). So the data is walked line by line as the header
// lays it out (`in` stands after the header, at byte `at`; blank lines are
// skipped, as assimp does): as many records as the header announces, each
// with a value for every property, each value at most 64 characters, each
// list count a whole number no larger than the values left on its line.
void check_ply_ascii_body(std::istream& in, const std::string& name, std::uintmax_t at,
                          const std::vector<PlyElement>& elements) {
  std::string line;
  std::vector<std::pair<std::string, std::uintmax_t>> values;  // a line's values and where each starts
  const auto next_record = [&]() {
    for (;;) {
      if (!bounded_getline(in, line, 1 << 20, name, "ASCII PLY data")) return false;
      values.clear();
      for (std::size_t i = 0; i < line.size(); ++i) {
        const auto u = static_cast<unsigned char>(line[i]);
        if ((u < 0x20 && u != '\t' && u != '\r') || u == 0x7f) {
          input_error("mesh '{}': its ASCII PLY data holds a control character (byte 0x{:02x}) at byte {}, where "
                      "ASCII data is numbers and spaces; the file is damaged, re-export the mesh",
                      name, static_cast<unsigned>(u), at + i);
        }
        if (std::isspace(u)) continue;
        if (i == 0 || std::isspace(static_cast<unsigned char>(line[i - 1]))) values.push_back({"", at + i});
        if (values.back().first.size() == 64) {
          input_error("mesh '{}': its ASCII PLY data holds a value of more than 64 characters at byte {}; the file "
                      "is damaged, re-export the mesh",
                      name, values.back().second);
        }
        values.back().first.push_back(line[i]);
      }
      at += line.size() + 1;
      if (!values.empty()) return true;
    }
  };
  for (const PlyElement& e : elements) {
    for (std::uintmax_t record = 0; record < e.count; ++record) {
      // Fewer records or values than the header announces made assimp's
      // reader take memory without end (20 GB in a minute, found by fuzzing).
      if (!next_record()) {
        input_error("mesh '{}': its ASCII PLY data ends after {} of the {} {} records its header announces; the "
                    "file is truncated or its header is wrong, re-export the mesh",
                    name, record, e.count, e.name);
      }
      std::size_t v = 0;
      for (const bool list : e.lists) {
        if (v == values.size()) {
          input_error("mesh '{}': {} {} (the line at byte {}) holds fewer values than the {} properties its header "
                      "gives it; the file is damaged, re-export the mesh",
                      name, e.name, record + 1, values.front().second, e.lists.size());
        }
        const auto& [count, count_at] = values[v++];
        if (!list) continue;
        const bool whole = count.find_first_not_of("0123456789") == std::string::npos;
        const std::uintmax_t n = !whole ? 0 : count.size() <= 18 ? std::stoull(count) : UINTMAX_MAX;
        if (!whole || n > values.size() - v) {
          input_error("mesh '{}': {} {} starts a list with the count '{}' at byte {}, {}; the file is damaged, "
                      "re-export the mesh",
                      name, e.name, record + 1, excerpt(count, 20), count_at,
                      whole ? fmt::format("more than the {} values left on its line", values.size() - v)
                            : std::string("not a whole number"));
        }
        v += n;
      }
    }
  }
  while (next_record()) {
  }
}

// Refuses a PLY whose header announces more elements than the file can hold.
void validate_ply(const std::filesystem::path& path, std::uintmax_t size) {
  const std::string name = path.string();
  std::ifstream in(path, std::ios::binary);
  std::string line;
  bool ascii = true;
  std::uintmax_t header = 0, need = 0;
  using Element = PlyElement;
  std::vector<Element> elements;
  const auto add = [&](const Element& e) {
    const std::uintmax_t per = std::max<std::uintmax_t>(e.min_bytes, 1);  // no property: still refuse absurd counts
    if (e.count > size / per) need = size + 1;  // also keeps count * per from overflowing
    else need += e.count * per;
    elements.push_back(e);
  };
  Element current;
  bool open_element = false, first_line = true, format_seen = false;
  while (header < 65536 && bounded_getline(in, line, 65536, name, "a PLY header")) {
    const std::uintmax_t line_start = header;
    header += line.size() + 1;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    // A NUL or other control character in the header (a binary file named
    // .ply, or a damaged header) made assimp's reader, which takes a NUL for
    // the end of a line, wait on the file forever (found by fuzzing).
    const auto control = std::find_if(line.begin(), line.end(), [](char c) {
      const auto u = static_cast<unsigned char>(c);
      return (u < 0x20 && c != '\t') || u == 0x7f;
    });
    if (control != line.end()) {
      input_error("mesh '{}': its PLY header holds a control character (byte 0x{:02x}) at byte {}, where a PLY "
                  "header is text; the file is damaged or not a PLY file, re-export the mesh",
                  name, static_cast<unsigned>(static_cast<unsigned char>(*control)),
                  line_start + static_cast<std::uintmax_t>(control - line.begin()));
    }
    std::istringstream words(line);
    std::string word;
    words >> word;
    // A PLY file starts with the line "ply". assimp's reader took other first
    // lines ("plyply") and waited on the file for ever (found by fuzzing), so
    // only a header checked whole to its end_header reaches it.
    if (std::exchange(first_line, false)) {
      std::string more;
      if (word != "ply" || words >> more) {
        input_error("mesh '{}': its first line is '{}', where a PLY file starts with the line 'ply'; the file is "
                    "damaged or not a PLY file, re-export the mesh",
                    name, excerpt(line, 40));
      }
      continue;
    }
    // A header line of no PLY keyword, or an unknown format, made assimp's
    // reader loop for minutes (found by fuzzing): refused here.
    if (word == "format") {
      // A second format line made grainlab and assimp read the data in two
      // ways (assimp took 9 GB, found by fuzzing).
      if (std::exchange(format_seen, true))
        input_error("mesh '{}': its PLY header gives 'format' twice; the file is damaged, re-export the mesh", name);
      std::string f;
      words >> f;
      if (f != "ascii" && f != "binary_little_endian" && f != "binary_big_endian")
        input_error("mesh '{}': PLY format '{}' is none of ascii, binary_little_endian, binary_big_endian; the file "
                    "is damaged, re-export the mesh",
                    name, excerpt(f, 40));
      ascii = f == "ascii";
    } else if (!word.empty() && word != "element" && word != "property" && word != "comment" && word != "obj_info" &&
               word != "end_header" && word != "ply") {
      input_error("mesh '{}': PLY header line '{}' starts with no PLY keyword (format, element, property, comment, "
                  "obj_info, end_header); the file is damaged, re-export the mesh",
                  name, excerpt(line, 80));
    } else if (word == "element") {
      if (open_element) add(current);
      current = {};
      open_element = true;
      words >> current.name >> current.count;
      if (!words) input_error("mesh '{}': PLY header line '{}' is not 'element NAME COUNT'; re-export the mesh", name,
                              excerpt(line, 80));
      // An element name of digits ("1111...vertex") made assimp ask for 80 GB
      // (found by fuzzing): a name is a word that starts with a letter.
      if (!std::isalpha(static_cast<unsigned char>(current.name[0])))
        input_error("mesh '{}': PLY header line '{}' names an element '{}', which does not start with a letter; "
                    "the file is damaged, re-export the mesh",
                    name, excerpt(line, 80), excerpt(current.name, 40));
      // An element or a property named twice corrupted assimp's memory (found
      // by fuzzing: a heap corruption).
      for (const Element& e : elements) {
        if (e.name == current.name)
          input_error("mesh '{}': its PLY header announces the element '{}' twice; the file is damaged, re-export the "
                      "mesh",
                      name, excerpt(current.name, 40));
      }
    } else if (word == "property") {
      // A property of an unknown type, or none, made assimp's binary reader
      // read out of bounds (found by fuzzing): each is 'property TYPE NAME' or
      // 'property list COUNT_TYPE ITEM_TYPE NAME' of PLY's scalar types.
      std::string type, count_type, item_type, property;
      words >> type;
      if (type == "list") words >> count_type >> item_type;
      words >> property;
      const bool known = type == "list" ? ply_type_size(count_type) > 0 && ply_type_size(item_type) > 0
                                        : ply_type_size(type) > 0;
      if (!open_element || !words || !known)
        input_error("mesh '{}': PLY header line '{}' is not 'property TYPE NAME' or 'property list COUNT_TYPE "
                    "ITEM_TYPE NAME' (types: char uchar short ushort int uint float double, or int8 ... float64) "
                    "after an 'element' line; the file is damaged, re-export the mesh",
                    name, excerpt(line, 80));
      current.min_bytes += ascii ? 2 : ply_type_size(type == "list" ? count_type : type);
      if (std::find(current.properties.begin(), current.properties.end(), property) != current.properties.end())
        input_error("mesh '{}': its PLY header gives element '{}' the property '{}' twice; the file is damaged, "
                    "re-export the mesh",
                    name, excerpt(current.name, 40), excerpt(property, 40));
      current.properties.push_back(property);
      current.lists.push_back(type == "list");
    } else if (word == "end_header") {
      // An end_header line without its line end (the file's last bytes) made
      // assimp's reader seek on the file for ever (found by fuzzing).
      if (in.eof()) {
        input_error("mesh '{}': its PLY header ends the file without a line end after 'end_header' and without "
                    "data; the file is truncated, re-export the mesh",
                    name);
      }
      if (open_element) add(current);
      const std::uintmax_t body = size - std::min(size, header);
      if (need > body) {
        std::string counts;
        for (const Element& e : elements) counts += fmt::format("{}{} {}", counts.empty() ? "" : ", ", e.count, e.name);
        input_error("mesh '{}': its PLY header announces {} elements ({}), which take at least {} bytes, but the "
                    "file holds {} bytes after its header; the file is truncated or its header is wrong, re-export "
                    "the mesh",
                    name, elements.size(), excerpt(counts, 200),
                    need > size ? fmt::format("more than the whole file's {}", size) : std::to_string(need), body);
      }
      if (ascii) check_ply_ascii_body(in, name, header, elements);
      return;
    }
  }
  if (first_line) return;  // an empty file: read_mesh says so
  // A header that never ends made assimp's reader take the data for header
  // lines and read out of bounds (found by fuzzing).
  input_error("mesh '{}': its PLY header has no 'end_header' line {}; the file is truncated or damaged, re-export "
              "the mesh",
              name, header >= 65536 ? "in its first 64 KiB" : "before the file's end");
}

// A user's path: a missing folder or a device is bad input (InputError), the rest a write failure.
void write_mesh_file(const std::filesystem::path& path, std::string_view bytes) {
  check_file_target(path);
  write_file_atomically(path, bytes);
}

}  // namespace

TriMesh read_mesh(const std::filesystem::path& path) {
  const std::string name = path.string();
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) {
    input_error("mesh '{}': file not found; check the path", name);
  }
  if (!std::filesystem::is_regular_file(path, ec)) {
    input_error("mesh '{}': not a regular file; give the path of an STL, OBJ or PLY file", name);
  }
  const std::string ext = lower(path.extension().string());
  if (ext != ".stl" && ext != ".obj" && ext != ".ply") {
    input_error("mesh '{}': unsupported file type '{}'; convert it to STL, OBJ or PLY", name, ext);
  }
  // 1 GiB: a scanned grain of 2000 faces is about 100 kB, a whole CT surface of millions of faces some 100 MB.
  const std::uintmax_t size = bounded_file_size(path, 1024 * kMiB, "mesh file");
  if (size == 0) input_error("mesh '{}': the file is empty (0 bytes); re-export the mesh", name);
  if (ext == ".stl") validate_stl(path, size);
  if (ext == ".ply") validate_ply(path, size);

  Assimp::Importer importer;
  // Drop normals, colours and texture coordinates. No assimp vertex joining:
  // its epsilon merged distinct vertices ~1 um apart in metre-unit grains; the
  // exact merge by position below is enough (repair_mesh merges near-duplicates
  // with a tolerance relative to the grain's size).
  importer.SetPropertyInteger(AI_CONFIG_PP_RVC_FLAGS,
                              aiComponent_NORMALS | aiComponent_TANGENTS_AND_BITANGENTS |
                                  aiComponent_COLORS | aiComponent_TEXCOORDS);
  const aiScene* scene = importer.ReadFile(path.string(), aiProcess_RemoveComponent);
  if (scene == nullptr) {
    input_error("mesh '{}': cannot be parsed ({}); check that it is a valid {} file or re-export it",
                name, importer.GetErrorString(), ext.substr(1));
  }
  // A face of no index (a crafted PLY) makes assimp's triangulation abort the
  // process (an assertion), and one whose index is past the mesh's vertices
  // (assimp's PLY reader does not check) made it read out of bounds (a
  // crash, found by fuzzing): refuse both before triangulating.
  for (unsigned mi = 0; mi < scene->mNumMeshes; ++mi) {
    const aiMesh* am = scene->mMeshes[mi];
    for (unsigned f = 0; f < am->mNumFaces; ++f) {
      const aiFace& af = am->mFaces[f];
      if (af.mNumIndices == 0)
        input_error("mesh '{}': face {} has no vertex; the file is damaged, re-export the mesh", name, f + 1);
      for (unsigned k = 0; k < af.mNumIndices; ++k)
        if (af.mIndices[k] >= am->mNumVertices)
          input_error("mesh '{}': face {} names vertex {}, but the mesh has {} vertices; the file is damaged, "
                      "re-export the mesh",
                      name, f + 1, af.mIndices[k], am->mNumVertices);
    }
  }
  scene = importer.ApplyPostProcessing(aiProcess_Triangulate);
  if (scene == nullptr) {
    input_error("mesh '{}': cannot be triangulated ({}); re-export it as triangles", name, importer.GetErrorString());
  }

  // Concatenate, merging exactly identical positions (by their bits, so that a
  // NaN vertex shared by several faces counts once) within and across meshes.
  TriMesh m;
  std::map<std::array<std::uint64_t, 3>, Index> seen;
  Index non_finite = 0;
  for (unsigned mi = 0; mi < scene->mNumMeshes; ++mi) {
    const aiMesh* am = scene->mMeshes[mi];
    std::vector<Index> local(am->mNumVertices);
    for (unsigned v = 0; v < am->mNumVertices; ++v) {
      const aiVector3D& p = am->mVertices[v];
      const Vec3 q(p.x, p.y, p.z);
      const std::array<std::uint64_t, 3> key = {std::bit_cast<std::uint64_t>(q.x()),
                                                 std::bit_cast<std::uint64_t>(q.y()),
                                                 std::bit_cast<std::uint64_t>(q.z())};
      const auto [it, inserted] = seen.try_emplace(key, static_cast<Index>(m.vertices.size()));
      if (inserted) {
        m.vertices.push_back(q);
        non_finite += !q.allFinite();
      }
      local[v] = it->second;
    }
    for (unsigned f = 0; f < am->mNumFaces; ++f) {
      const aiFace& af = am->mFaces[f];
      if (af.mNumIndices != 3) continue;  // points and lines bound no solid
      m.faces.push_back({local[af.mIndices[0]], local[af.mIndices[1]], local[af.mIndices[2]]});
    }
  }
  if (non_finite) {
    input_error("mesh '{}': {} {} non-finite (NaN or infinite) coordinates; re-export the mesh",
                name, non_finite, non_finite == 1 ? "vertex has" : "vertices have");
  }
  if (m.faces.empty()) {
    input_error("mesh '{}': the file holds no triangles (empty mesh); re-export the grain's surface", name);
  }
  return m;
}

void write_stl(const TriMesh& mesh, const std::filesystem::path& path) {
  std::string bytes(84 + 50 * mesh.faces.size(), '\0');
  const char header[] = "grainlab binary STL";
  std::memcpy(bytes.data(), header, sizeof(header) - 1);
  const auto n = static_cast<std::uint32_t>(mesh.faces.size());
  std::memcpy(bytes.data() + 80, &n, 4);
  char* p = bytes.data() + 84;
  for (const Face& f : mesh.faces) {
    const Vec3 &a = mesh.vertices[f[0]], &b = mesh.vertices[f[1]], &c = mesh.vertices[f[2]];
    Vec3 normal = (b - a).cross(c - a);
    const double len = normal.norm();
    normal = len > 0 ? Vec3(normal / len) : Vec3::Zero();
    float rec[12];
    for (int k = 0; k < 3; ++k) {
      rec[k] = static_cast<float>(normal[k]);
      rec[3 + k] = static_cast<float>(a[k]);
      rec[6 + k] = static_cast<float>(b[k]);
      rec[9 + k] = static_cast<float>(c[k]);
    }
    std::memcpy(p, rec, 48);  // the 2-byte attribute stays zero
    p += 50;
  }
  write_mesh_file(path, bytes);
}

void write_obj(const TriMesh& mesh, const std::filesystem::path& path) {
  fmt::memory_buffer buf;
  fmt::format_to(std::back_inserter(buf), "# grainlab mesh: {} vertices, {} faces\n",
                 mesh.vertices.size(), mesh.faces.size());
  for (const Vec3& v : mesh.vertices) {
    fmt::format_to(std::back_inserter(buf), "v {:.17g} {:.17g} {:.17g}\n", v.x(), v.y(), v.z());
  }
  for (const Face& f : mesh.faces) {
    fmt::format_to(std::back_inserter(buf), "f {} {} {}\n", f[0] + 1, f[1] + 1, f[2] + 1);
  }
  write_mesh_file(path, std::string(buf.data(), buf.size()));
}

}  // namespace grainlab
