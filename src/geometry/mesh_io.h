// Reading and writing triangle mesh files (STL, OBJ, PLY).
#pragma once

#include "geometry/trimesh.h"

#include <filesystem>

namespace grainlab {

// Reads every triangle of an STL (ASCII or binary), OBJ or PLY file, all meshes in
// the file concatenated, identical positions merged, winding as in the file (no
// repair: use load_mesh() for users' files). STL and OBJ coordinates pass
// through assimp in single precision; PLY ones (geometry/ply_reader.h) keep
// their scalar type's precision. Throws InputError naming the file, the defect
// and a fix.
TriMesh read_mesh(const std::filesystem::path& path);

// Writes a binary STL (single precision), through a temporary file renamed into place.
void write_stl(const TriMesh& mesh, const std::filesystem::path& path);

// Writes a Wavefront OBJ (17 significant digits), through a temporary file renamed into place.
void write_obj(const TriMesh& mesh, const std::filesystem::path& path);

}  // namespace grainlab
