// mohr_coulomb.json: the Mohr-Coulomb envelopes fitted over several drained
// triaxial runs (analysis/mohr_coulomb.h), written next to their comparison
// report by `grainlab report` (grainlab.report draws it, fits nothing).
//
// Each run gives two circles, at its peak and at its critical state, from its
// run.json: sigma_3 = config.consolidation.normal_stress (the cell pressure
// its sides' servos held) and eta = triaxial.peak_stress_ratio or
// triaxial.critical_stress_ratio, sigma_1 = sigma_3 (3 + 2 eta)/(3 - eta).
// The file (SI units):
//   "what", "source"                  what was fitted, from which keys
//   "peak", "critical_state"          {"phi_deg", "c_Pa", "a_Pa", "sin_phi",
//                                     "r_squared", "rms_residual_Pa", "runs"},
//                                     or {"phi_deg": null, "c_Pa": null,
//                                     "refused": why} when no envelope fits
//   "runs"                            by sigma_3: {"name", "folder",
//                                     "sigma3_Pa", "peak", "critical_state"},
//                                     each state {"stress_ratio", "sigma1_Pa",
//                                     "sigma3_Pa", "s_Pa", "t_Pa",
//                                     "friction_angle_deg" (the run's own,
//                                     c' = 0)} or null without its stresses
#pragma once

#include <filesystem>
#include <vector>

namespace grainlab {

// Whether there are several runs and every one's run.json reads as a
// triaxial run's (false otherwise, also for an unreadable run.json: the
// report script says what is wrong with it).
bool is_triaxial_comparison(const std::vector<std::filesystem::path>& runs);

// Writes out_dir/mohr_coulomb.json (above) for the runs, creating out_dir.
void write_mohr_coulomb_file(const std::vector<std::filesystem::path>& runs, const std::filesystem::path& out_dir);

}  // namespace grainlab
