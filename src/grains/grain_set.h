// Grain libraries a specimen draws from: generated or imported meshes, each
// centred, in its principal frame and scaled to a sieve range.
//
// Size: the intermediate principal dimension I (extent along the intermediate
// axis of inertia). A grain passes a square sieve opening when its
// cross-section across the long axis fits, which is governed by I (S <= I), so
// I is the size a sieve sorts by; for spheres it is the diameter.
#pragma once

#include "grains/generator.h"
#include "grains/sh_grain.h"

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace grainlab {

// A sieve fraction by its openings, in m: passing d_max, retained on d_min.
// Default: passing #20 (0.841 mm), retained on #25 (0.707 mm), the paper's sands.
struct SieveRange {
  double d_min = 0.707e-3;
  double d_max = 0.841e-3;
};

// Throws InputError unless 0 < d_min <= d_max, both finite.
void validate(const SieveRange& sieve);

struct GrainSet {
  std::vector<TriMesh> meshes;      // each centred at its centroid, in its principal frame, at physical size (m)
  std::vector<std::string> names;   // one per mesh: "<preset>-0001" or the imported file's stem
  bool spheres = false;             // glass beads: the engine uses its analytic sphere path
  std::vector<std::string> notes;   // what import had to give up (budget raised, ...), for the user
};

// The size a sieve sorts by: the intermediate principal dimension I, in m.
double size_of(const TriMesh& mesh);

// `count` grains of a preset. Sizes (size_of) spread uniformly over the sieve
// range (one size per equal slice of the range, jittered and shuffled), so even
// a small set spans it. The same arguments give the same meshes bit for bit,
// whatever the thread count.
GrainSet generate_grain_set(GrainPreset preset, int count, std::uint64_t seed, SieveRange sieve = {},
                            int faces = 2000);
GrainSet generate_grain_set(const GeneratorSpec& spec, int count, std::uint64_t seed, SieveRange sieve = {});

// `count` grains of an SH sand preset (sh_sands.h: "sh-ottawa", ...) drawn by
// the shape-model method at `faces` faces (generate_sh_grains), sized over
// the sieve range as generate_grain_set sizes them; named "<preset>-0001".
// The same arguments give the same meshes bit for bit, whatever the thread
// count. Throws InputError for an unknown name (listing the SH sands).
GrainSet generate_sh_grain_set(const std::string& sand, int count, std::uint64_t seed, SieveRange sieve = {},
                               int faces = 2000);

// True for the files a grain folder holds: meshes (.stl, .obj, .ply) and
// spherical-harmonic coefficient files (.dat, sh_grain.h), in any case.
bool is_grain_file(const std::filesystem::path& path);

// One grain file as a closed mesh: an SH file meshed at `sh_faces` faces and
// brought to metres by `sh_options` (load_sh_grain), or a mesh file read,
// checked and repaired as it is (load_mesh; its coordinates taken as metres;
// what the repair did goes to `notes` when given).
TriMesh load_grain_file(const std::filesystem::path& path, int sh_faces, const ShOptions& sh_options,
                        std::vector<std::string>* notes = nullptr);

// Every grain file in `folder` (is_grain_file; not recursive), sorted by name:
// a mesh read, checked and repaired (load_mesh), simplified to `face_budget`
// keeping volume within 1 % and the mesh closed (budget raised when it cannot;
// noted); an SH file meshed at `face_budget` faces directly (sh_mesh). Each
// is centred and rotated into the principal frame, and scaled so that sizes
// spread over the sieve range in the grains' own size order (the largest
// scanned grain becomes the largest in the set). Throws InputError for a
// missing or empty folder, or a bad file (naming it).
GrainSet import_grain_set(const std::filesystem::path& folder, int face_budget, SieveRange sieve = {});

}  // namespace grainlab
