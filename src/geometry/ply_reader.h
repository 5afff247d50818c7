// Reading a PLY (Stanford polygon) mesh file: grainlab's own reader, so that
// every count in the file is held to the file's bytes and the machine's
// memory before anything is allocated (the format is described at the top of
// ply_reader.cpp).
#pragma once

#include "geometry/trimesh.h"

#include <cstdint>
#include <filesystem>

namespace grainlab {

// The vertices (in the file's order, in double precision whatever their
// scalar type) and the faces of the PLY file `path` of `size` bytes, each
// polygon cut into triangles (a fan from its first corner that folds no
// triangle over). Indices are checked against the vertices; positions are not
// (read_mesh merges and checks them). Throws InputError naming the file, the
// defect, where it is (a byte offset) and a fix.
TriMesh read_ply(const std::filesystem::path& path, std::uintmax_t size);

}  // namespace grainlab
