#include "ct/segmentation_files.h"

#include "core/error.h"
#include "core/atomic_file.h"
#include "geometry/mesh_io.h"

#include <fmt/format.h>
#include <unistd.h>

#include <vector>

namespace grainlab::ct {

namespace fs = std::filesystem;

namespace {

bool is_our_file(const fs::path& p) {
  const std::string name = p.filename().string();
  return name == "grains.csv" || name == "grain_quality.csv" ||
         (name.rfind("grain_", 0) == 0 && (p.extension() == ".stl" || p.extension() == ".obj"));
}

}  // namespace

void check_output_folder(const fs::path& out, bool force) {
  std::error_code ec;
  if (!fs::exists(out, ec)) return;
  if (!fs::is_directory(out, ec)) input_error("--out '{}' exists and is not a folder: choose another path", out.string());
  if (!force && !fs::is_empty(out, ec)) {
    input_error("output folder '{}' is not empty: choose a new folder, empty it, or give --force to replace the "
                "grain meshes and grains.csv in it",
                out.string());
  }
}

std::string mesh_file_name(int id, const std::string& mesh_format) {
  return fmt::format("grain_{:04d}.{}", id, mesh_format);
}

std::string grains_csv(const Segmentation& s, const std::string& mesh_format) {
  std::string csv = std::string(kGrainsCsvHeader) + "\n";
  for (const SegmentedGrain& g : s.grains) {
    const Quat& q = g.orientation;
    csv += fmt::format("{},{},{:.9e},{:.9e},{:.9e},{:.9f},{:.9f},{:.9f},{:.9f},{:.9e},{:.9e},{}\n", g.id,
                       mesh_file_name(g.id, mesh_format), g.centroid.x(), g.centroid.y(), g.centroid.z(), q.w(),
                       q.x(), q.y(), q.z(), g.volume, g.equivalent_diameter, g.border ? 1 : 0);
  }
  return csv;
}

std::string grain_quality_csv(const Segmentation& s) {
  std::string csv = std::string(kGrainQualityCsvHeader) + "\n";
  for (const SegmentedGrain& g : s.grains) {
    const GrainQuality& q = g.quality;
    csv += fmt::format("{},{},{:.9e},{:.9e},{:.6f},{},{},{:.9e},{:.6f},{},{}\n", g.id, g.voxels, g.volume,
                       g.equivalent_diameter, q.convexity, q.distance_maxima, q.contacts, q.contact_area,
                       q.largest_contact_ratio, q.likely_merge ? 1 : 0, q.likely_split ? 1 : 0);
  }
  return csv;
}

void write_segmentation(const Segmentation& s, const fs::path& out, bool force, const std::string& mesh_format) {
  if (mesh_format != "stl" && mesh_format != "obj") input_error("--format '{}': use stl or obj", mesh_format);
  check_output_folder(out, force);
  const fs::path target = fs::absolute(out).lexically_normal();
  const fs::path parent = target.has_filename() ? target.parent_path() : target.parent_path().parent_path();
  const std::string name = target.has_filename() ? target.filename().string() : target.parent_path().filename().string();
  std::error_code ec;
  fs::create_directories(parent, ec);
  if (ec) input_error("cannot create the folder '{}' for --out: {}", parent.string(), ec.message());
  const fs::path staging = parent / fmt::format(".{}.partial.{}", name, ::getpid());
  fs::remove_all(staging, ec);
  fs::create_directory(staging, ec);
  if (ec) throw RunError(fmt::format("cannot create '{}': {}", staging.string(), ec.message()));
  try {
    for (const SegmentedGrain& g : s.grains) {
      const fs::path p = staging / mesh_file_name(g.id, mesh_format);
      if (mesh_format == "stl") {
        write_stl(g.mesh, p);
      } else {
        write_obj(g.mesh, p);
      }
    }
    write_file_atomically(staging / "grains.csv", grains_csv(s, mesh_format));
    write_file_atomically(staging / "grain_quality.csv", grain_quality_csv(s));

    const fs::path final_dir = parent / name;
    if (!fs::exists(final_dir)) {
      fs::rename(staging, final_dir);
      return;
    }
    // The folder exists (empty, or --force): replace our earlier files, then move the new ones in.
    std::vector<fs::path> old;
    for (const auto& e : fs::directory_iterator(final_dir)) {
      if (e.is_regular_file() && is_our_file(e.path())) old.push_back(e.path());
    }
    for (const fs::path& p : old) fs::remove(p);
    for (const SegmentedGrain& g : s.grains) {
      const std::string f = mesh_file_name(g.id, mesh_format);
      fs::rename(staging / f, final_dir / f);
    }
    fs::rename(staging / "grain_quality.csv", final_dir / "grain_quality.csv");
    fs::rename(staging / "grains.csv", final_dir / "grains.csv");
    fs::remove_all(staging);
  } catch (const fs::filesystem_error& e) {
    fs::remove_all(staging, ec);
    throw RunError(fmt::format("cannot write the segmentation into '{}': {}", out.string(), e.what()));
  } catch (...) {
    fs::remove_all(staging, ec);
    throw;
  }
}

}  // namespace grainlab::ct
