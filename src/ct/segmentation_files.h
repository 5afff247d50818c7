// The files `grainlab ct segment` writes: one mesh per grain (grain_0001.stl,
// ...), grains.csv and grain_quality.csv, all or nothing.
//
// Everything is first written into a hidden staging folder next to the output
// folder; when complete, the staging folder is renamed onto the output folder
// (or, when that exists, each file is renamed into it), so a killed run leaves
// at most the hidden staging folder, never a half-written file or a
// grains.csv that names missing meshes.
#pragma once

#include "ct/segmentation.h"

#include <filesystem>
#include <string>

namespace grainlab::ct {

// Throws InputError when `out` exists and is not an empty folder, unless `force`
// (then earlier grain_*.stl|obj, grains.csv and grain_quality.csv in it are replaced).
void check_output_folder(const std::filesystem::path& out, bool force);

// The header line of grains.csv.
inline constexpr const char* kGrainsCsvHeader =
    "id,file,x_m,y_m,z_m,qw,qx,qy,qz,volume_m3,equivalent_diameter_m,border";

// The header line of grain_quality.csv.
inline constexpr const char* kGrainQualityCsvHeader =
    "id,voxels,volume_m3,equivalent_diameter_m,convexity,distance_maxima,contacts,contact_area_m2,"
    "largest_contact_ratio,likely_merge,likely_split";

// grain_quality.csv's text: one row per grain (grain_quality.h).
std::string grain_quality_csv(const Segmentation& s);

// grains.csv's text: one row per grain (file names as mesh_file_name gives).
std::string grains_csv(const Segmentation& s, const std::string& mesh_format);

// "grain_0007.stl" for grain 7 and format "stl".
std::string mesh_file_name(int id, const std::string& mesh_format);

// Writes the meshes (format "stl" or "obj") and grains.csv into `out`.
void write_segmentation(const Segmentation& s, const std::filesystem::path& out, bool force,
                        const std::string& mesh_format);

}  // namespace grainlab::ct
