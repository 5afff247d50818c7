// The final analysis of a direct shear run: the files of the run folder's
// analysis/ subfolder that scripts/report.py reads (its docstring is the
// contract), each written atomically. SI units; heights in the world frame
// (floor at z = 0); x is the shear direction.
//
//   profile.csv       z_m, displacement_x_m, count: mean horizontal grain
//                     displacement since the start of shear per layer of
//                     reference height (the binning of io/shear_analysis.h:
//                     layers about one mean grain diameter thick, floor to cap)
//   band.json         {"found", "low_m", "high_m", "mid_m", "u_bottom_m",
//                     "u_top_m", "method", ...}: the band of that profile
//                     (low_m/high_m null when none was found)
//   fabric.json       {"all": {...}, "band": {...}}: contact-normal fabric of
//                     all grain-grain contacts and of the contacts of the grains
//                     in the band (fabric_entry below)
//   force_chains.csv  x1_m, y1_m, z1_m, x2_m, y2_m, z2_m, force_N,
//                     tangential_force_N: one grain-grain contact per row, a
//                     segment between the two grain centres; force_N is the
//                     normal contact force (N), the measure analysis/force_stats.h
//                     splits strong and weak chains by
#pragma once

#include "analysis/grain_mask.h"
#include "dynamics/state.h"
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
// "normals_subsampled": true, with "normals_total" and "normals_written").
// Without contacts: {"contacts": 0, "note": ...} only.
nlohmann::json fabric_entry(const State& state, const analysis::GrainMask* mask,
                            std::size_t max_normals = kMaxFabricNormals);

// Writes folder/analysis/{profile.csv, band.json, fabric.json, force_chains.csv}
// for the test's current state (creating analysis/; RunError if a write fails).
void write_analysis_files(const LabTest& test, const std::filesystem::path& folder);

}  // namespace grainlab
