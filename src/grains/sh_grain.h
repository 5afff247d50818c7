// Grains described by spherical harmonics (SH): Garboczi's coefficient files
// (NIST VCCTL, CT-scanned particles) read, checked, written, and turned into
// the closed triangle meshes the rest of grainlab works with.
//
// File format: one line per coefficient, `n m Re(a_nm) Im(a_nm)` separated by
// blanks (VCCTL writes `%4d%4d%20.10f%20.10f`), every (n, m) with |m| <= n
// for n = 0..N exactly once, in any order (VCCTL's: n = 0..N, m = n..-n); no
// header. The unit of r is the file's (not stated in it).
#pragma once

#include "geometry/spherical_harmonics.h"
#include "geometry/trimesh.h"

#include <filesystem>
#include <string>

namespace grainlab {

// Extension of SH coefficient files.
inline constexpr const char* kShExtension = ".dat";

// Reads an SH file. Throws InputError naming the file and line for a line
// that is not four numbers (a truncated last line included), an (n, m) with
// |m| > n or n > 200, a value that is not finite, a pair given twice (both
// lines named), a missing pair (a truncated file), or a_00 <= 0.
ShCoefficients read_sh_file(const std::filesystem::path& path);

// Writes `c` in VCCTL's layout (n = 0..N, m = n..-n, `%4d%4d%20.10f%20.10f`),
// atomically. Values are rounded to 10 decimals of the file's unit.
void write_sh_file(const ShCoefficients& c, const std::filesystem::path& path);

// The surface r(u) u of `c` on a sphere mesh of exactly `faces` triangles
// (faces / 2 + 2 Fibonacci directions, triangulated as their convex hull), in
// the coefficients' unit, about the file's origin. Throws InputError naming
// `name` and the direction (theta, phi) where r <= 0, at a vertex or on a
// finer grid between them. With r > 0 the mesh is closed, outward and cannot
// fold over itself (proof in sh_grain.cpp). faces >= 8.
TriMesh sh_mesh(const ShCoefficients& c, int faces, const std::string& name);

// How to mesh an SH grain: bring it to metres by multiplying by `unit`
// (metres per unit of the file; 1e-3 for millimetres), or, when d_eq > 0, by
// scaling it to that volume-equivalent diameter (m) instead; with
// max_degree >= 0, only the degrees n <= max_degree (a smoother grain).
struct ShOptions {
  double unit = 1e-3;
  double d_eq = 0;
  int max_degree = -1;
};

// The first degrees of `c`, n <= degree (all of them if degree >= c.degree).
ShCoefficients truncated(const ShCoefficients& c, int degree);

// read_sh_file, truncated, sh_mesh and the scale: the grain in metres, about the file's origin.
TriMesh load_sh_grain(const std::filesystem::path& path, int faces, const ShOptions& scale);

// True for a path with the SH extension (any case).
bool is_sh_file(const std::filesystem::path& path);

}  // namespace grainlab
