// Grain sets (see grain_set.h).
#include "core/text.h"
#include "grains/grain_set.h"

#include "core/error.h"
#include "core/parallel.h"
#include "geometry/mesh_check.h"
#include "geometry/shape_metrics.h"
#include "geometry/simplify.h"
#include "grains/sh_sands.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <numeric>

namespace grainlab {
namespace {

// Target sizes: one per equal slice of [d_min, d_max], jittered within its
// slice, in random order (Fisher-Yates on the set's generator).
std::vector<double> sieve_sizes(const SieveRange& sieve, int count, Rng& rng) {
  std::vector<double> d(static_cast<std::size_t>(count));
  for (int k = 0; k < count; ++k) {
    d[k] = sieve.d_min + (k + rng.uniform()) / count * (sieve.d_max - sieve.d_min);
  }
  for (int k = count - 1; k > 0; --k) {
    const int j = static_cast<int>(rng.next_u64() % static_cast<std::uint64_t>(k + 1));
    std::swap(d[k], d[j]);
  }
  return d;
}

void scale_to(TriMesh& mesh, double size) {
  const double s = size / size_of(mesh);
  for (Vec3& v : mesh.vertices) v *= s;
}

}  // namespace

void validate(const SieveRange& s) {
  if (!(s.d_min > 0 && s.d_max >= s.d_min) || !std::isfinite(s.d_max)) {
    input_error("sieve range must satisfy 0 < d_min <= d_max (m), got d_min {} and d_max {}", s.d_min, s.d_max);
  }
}

bool is_grain_file(const std::filesystem::path& path) {
  const std::string ext = lower(path.extension().string());
  return ext == ".stl" || ext == ".obj" || ext == ".ply" || is_sh_file(path);
}

TriMesh load_grain_file(const std::filesystem::path& path, int sh_faces, const ShOptions& sh_options,
                        std::vector<std::string>* notes) {
  return is_sh_file(path) ? load_sh_grain(path, sh_faces, sh_options) : load_mesh(path, notes);
}

double size_of(const TriMesh& mesh) { return principal_frame(mesh).extents[1]; }

GrainSet generate_grain_set(GrainPreset preset, int count, std::uint64_t seed, SieveRange sieve, int faces) {
  GeneratorSpec spec = preset_spec(preset);
  spec.faces = faces;
  return generate_grain_set(spec, count, seed, sieve);
}

GrainSet generate_grain_set(const GeneratorSpec& spec, int count, std::uint64_t seed, SieveRange sieve) {
  validate(spec);
  validate(sieve);
  if (count < 1) input_error("grain count must be at least 1, got {}", count);
  // One generator for the set (sizes, per-grain seeds); one per grain, so the
  // grains can be built in parallel and still come out the same.
  Rng rng(seed);
  const std::vector<double> sizes = sieve_sizes(sieve, count, rng);
  std::vector<std::uint64_t> seeds(static_cast<std::size_t>(count));
  for (auto& s : seeds) s = rng.next_u64();

  GrainSet set;
  set.meshes.resize(seeds.size());
  set.spheres = spec.roundness >= 1.0 && spec.elongation >= 1.0 && spec.flatness >= 1.0 &&
                spec.aspect_spread == 0 && spec.convexity >= 1.0;  // dented beads are not spheres
  parallel_for(
      count,
      [&](std::ptrdiff_t k) {
        Rng grain_rng(seeds[k]);
        TriMesh m = generate_grain(spec, grain_rng);
        scale_to(m, sizes[k]);
        set.meshes[k] = std::move(m);
      },
      1);
  for (int k = 0; k < count; ++k) set.names.push_back(fmt::format("{}-{:04d}", grain_preset_name(spec.preset), k + 1));
  return set;
}

GrainSet generate_sh_grain_set(const std::string& name, int count, std::uint64_t seed, SieveRange sieve, int faces) {
  const ShSand* sand = find_sh_sand(name);
  if (!sand) input_error("unknown spherical-harmonic sand '{}': use one of {}", name, sh_sand_names());
  validate(sieve);
  if (count < 1) input_error("grain count must be at least 1, got {}", count);
  Rng rng(seed);
  const std::vector<double> sizes = sieve_sizes(sieve, count, rng);
  ShGrains grains = generate_sh_grains(sand->spectrum, count, rng.next_u64(), faces, ShMethod::shape_model);
  GrainSet set;
  for (int k = 0; k < count; ++k) {
    scale_to(grains.meshes[k], sizes[k]);
    set.meshes.push_back(std::move(grains.meshes[k]));
    set.names.push_back(fmt::format("{}-{:04d}", name, k + 1));
  }
  return set;
}

GrainSet import_grain_set(const std::filesystem::path& folder, int face_budget, SieveRange sieve) {
  validate(sieve);
  if (!std::filesystem::is_directory(folder)) {
    input_error("grain folder '{}' does not exist or is not a folder", folder.string());
  }
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    if (entry.is_regular_file() && is_grain_file(entry.path())) files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  if (files.empty()) {
    input_error("grain folder '{}' holds no .stl, .obj, .ply or .dat (spherical-harmonic) file; put one file per "
                "grain there",
                folder.string());
  }
  GrainSet set;
  std::vector<double> measured;
  for (const auto& file : files) {
    // An SH grain is meshed at the budget directly (its size is set below, so its unit does not matter).
    SimplifyResult s = is_sh_file(file) ? SimplifyResult{load_sh_grain(file, face_budget, ShOptions{1.0, 0})}
                                        : simplify_mesh(load_mesh(file), face_budget);
    if (!s.within_budget) {
      set.notes.push_back(fmt::format("{}: {} faces could not keep the volume within 1 % and the mesh closed; "
                                      "kept {} faces (volume error {:.2f} %)",
                                      file.filename().string(), face_budget, s.mesh.faces.size(),
                                      100 * s.volume_error));
    }
    move_to_principal_frame(s.mesh);
    measured.push_back(size_of(s.mesh));
    set.meshes.push_back(std::move(s.mesh));
    set.names.push_back(file.stem().string());
  }
  // Rank the grains by their own size and give the k-th smallest the centre of
  // the k-th equal slice of the sieve range.
  const int n = static_cast<int>(files.size());
  std::vector<int> order(static_cast<std::size_t>(n));
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return measured[a] < measured[b]; });
  for (int rank = 0; rank < n; ++rank) {
    const double d = sieve.d_min + (rank + 0.5) / n * (sieve.d_max - sieve.d_min);
    scale_to(set.meshes[order[rank]], d);
  }
  return set;
}

}  // namespace grainlab
