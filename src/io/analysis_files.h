// The final analysis of a direct shear run: the files of the run folder's
// analysis/ subfolder that grainlab.report reads (its docstring is the
// contract), each written atomically. The numbers are the analysis layer's
// result structs (analysis/band_analysis.h, fabric_result.h, force_chains.h,
// dilation.h), serialised here without further maths. SI units; heights in
// the world frame (floor at z = 0); x is the shear direction.
//
//   profile.csv       z_m, displacement_x_m, count: mean horizontal grain
//                     displacement since the start of shear per layer of
//                     reference height (analysis/band_analysis.h: layers about
//                     one mean grain diameter thick, floor to cap)
//   band.json         {"found", "low_m", "high_m", "mid_m", "u_bottom_m",
//                     "u_top_m", "method", ...}: the band of that profile
//                     (low_m/high_m null when none was found)
//   fabric.json       {"all": {...}, "band": {...}}: contact-normal fabric of
//                     all grain-grain contacts and of the contacts of the grains
//                     in the band (fabric_json below)
//   force_chains.csv  x1_m, y1_m, z1_m, x2_m, y2_m, z2_m, force_N,
//                     tangential_force_N, strong (1: normal force above the
//                     mean, analysis/force_stats.h): one grain-grain contact per row, a
//                     segment between the two grain centres; force_N is the
//                     normal contact force (N), the measure analysis/force_stats.h
//                     splits strong and weak chains by
//   derived.csv       shear_strain, dilation_angle_deg: one row per row of
//                     series.csv, the dilation angle of analysis/dilation.h
//                     (Eq. 19; nan where undefined)
#pragma once

#include "analysis/fabric_result.h"
#include "lab/lab_test.h"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <filesystem>

namespace grainlab {

// Normals listed in fabric.json at most (per set); more are evenly subsampled.
inline constexpr std::size_t kMaxFabricNormals = 20000;

// One fabric.json set: "contacts" (normals counted), "phi" (3x3), "D2" (3x3,
// Kanatani's D_ij = 15/2 dev phi), "D4" (3x3x3x3, D_ijkl = 315/8 dev phi_ijkl),
// "principal_values" (3, largest first), "principal_directions" (3x3, columns),
// "psi" (Eq. 29), "normals" ([[nx, ny, nz], ...]); the tensors are over every
// normal, the list holds at most max_normals of them, evenly subsampled (then
// "normals_subsampled": true, with "normals_total" and "normals_written");
// "rose": {"z_edges", "azimuth_edges_rad", "density_per_sr" (n_z x n_az)}, the
// rose histogram of every normal, and "kanatani_grid": {"theta_rad",
// "phi_rad", "density_per_sr" (n_theta x n_phi)} (analysis/rose.h).
// Without contacts: {"contacts": 0, "note": ...} only.
nlohmann::json fabric_json(const analysis::FabricResult& fabric, std::size_t max_normals = kMaxFabricNormals);

// Writes folder/analysis/{profile.csv, band.json, fabric.json,
// force_chains.csv, derived.csv} for the test's current state (creating
// analysis/; RunError if a write fails).
void write_analysis_files(const LabTest& test, const std::filesystem::path& folder);

}  // namespace grainlab
