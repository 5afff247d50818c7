// Mesh files in and out. assimp parses STL and OBJ, grainlab's own reader
// PLY (geometry/ply_reader.h); grainlab checks what assimp is lenient about
// (a truncated binary STL, an empty file) and turns every failure into a
// message naming the file, the defect and a fix.
//
// Binary STL layout: 80-byte header, uint32 triangle count n (little
// endian), then n records of 50 bytes (normal and three vertices as 12
// float32, then a uint16 attribute), so a whole file is 84 + 50 n bytes.
// An ASCII STL starts with "solid"; a binary header may too, so the size
// test decides first.
#include "core/text.h"
#include "geometry/mesh_io.h"
#include "geometry/ply_reader.h"

#include "core/atomic_file.h"
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
#include <system_error>

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

// A user's path: a missing folder or a device is bad input (InputError), the rest a write failure.
void write_mesh_file(const std::filesystem::path& path, std::string_view bytes) {
  check_file_target(path);
  write_file_atomically(path, bytes);
}

// Appends `piece` to `m`, merging exactly identical positions (by their
// bits, so that a NaN vertex shared by several faces counts once) with those
// already in `m` (`seen`); counts the non-finite vertices added.
void append_merged(const TriMesh& piece, TriMesh& m, std::map<std::array<std::uint64_t, 3>, Index>& seen,
                   Index& non_finite) {
  std::vector<Index> local(piece.vertices.size());
  for (std::size_t v = 0; v < piece.vertices.size(); ++v) {
    const Vec3& q = piece.vertices[v];
    const std::array<std::uint64_t, 3> key = {std::bit_cast<std::uint64_t>(q.x()), std::bit_cast<std::uint64_t>(q.y()),
                                               std::bit_cast<std::uint64_t>(q.z())};
    const auto [it, inserted] = seen.try_emplace(key, static_cast<Index>(m.vertices.size()));
    if (inserted) {
      m.vertices.push_back(q);
      non_finite += !q.allFinite();
    }
    local[v] = it->second;
  }
  for (const Face& f : piece.faces) m.faces.push_back({local[f[0]], local[f[1]], local[f[2]]});
}

// The triangles of each mesh assimp reads from the STL or OBJ file `path`.
std::vector<TriMesh> read_with_assimp(const std::filesystem::path& path, const std::string& ext) {
  const std::string name = path.string();
  Assimp::Importer importer;
  // Drop normals, colours and texture coordinates. No assimp vertex joining:
  // its epsilon merged distinct vertices ~1 um apart in metre-unit grains; the
  // exact merge by position in read_mesh is enough (repair_mesh merges
  // near-duplicates with a tolerance relative to the grain's size).
  importer.SetPropertyInteger(AI_CONFIG_PP_RVC_FLAGS,
                              aiComponent_NORMALS | aiComponent_TANGENTS_AND_BITANGENTS |
                                  aiComponent_COLORS | aiComponent_TEXCOORDS);
  const aiScene* scene = importer.ReadFile(path.string(), aiProcess_RemoveComponent);
  if (scene == nullptr) {
    input_error("mesh '{}': cannot be parsed ({}); check that it is a valid {} file or re-export it",
                name, importer.GetErrorString(), ext.substr(1));
  }
  // A face of no index makes assimp's triangulation abort the process (an
  // assertion), and one whose index is past the mesh's vertices made it read
  // out of bounds: refuse both before triangulating.
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
  std::vector<TriMesh> meshes(scene->mNumMeshes);
  for (unsigned mi = 0; mi < scene->mNumMeshes; ++mi) {
    const aiMesh* am = scene->mMeshes[mi];
    for (unsigned v = 0; v < am->mNumVertices; ++v)
      meshes[mi].vertices.emplace_back(am->mVertices[v].x, am->mVertices[v].y, am->mVertices[v].z);
    for (unsigned f = 0; f < am->mNumFaces; ++f) {
      const aiFace& af = am->mFaces[f];
      if (af.mNumIndices != 3) continue;  // points and lines bound no solid
      meshes[mi].faces.push_back({static_cast<Index>(af.mIndices[0]), static_cast<Index>(af.mIndices[1]),
                                  static_cast<Index>(af.mIndices[2])});
    }
  }
  return meshes;
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
  const std::vector<TriMesh> pieces = ext == ".ply" ? std::vector<TriMesh>{read_ply(path, size)}
                                                    : read_with_assimp(path, ext);

  // Concatenate, merging exactly identical positions within and across meshes.
  TriMesh m;
  std::map<std::array<std::uint64_t, 3>, Index> seen;
  Index non_finite = 0;
  for (const TriMesh& piece : pieces) append_merged(piece, m, seen, non_finite);
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
