// How many grains a specimen needs and how much memory they would take, so
// that a box too large for the machine is refused before anything is built.
//
// Grain count: N = L W H / ((1 + e) V_mean), the placement's rule
// (lab/specimen.h), in double precision (a 1 m box of 0.8 mm grains needs
// about 2.3e9 grains: more than an int holds).
//
// Bytes per grain: the sizes of the real structures a grain occupies during a
// run (sizeof on this build), times how many of each a grain has:
//   per grain, once:   BodyModel, BodyState, x_at_rebuild (Vec3), the
//                      World's force, torque (2 Vec3), rotation (Mat3), AABB
//                      and kinetic energy (double), and the protocol's
//                      reference BodyState and force-window sum (Vec3);
//   per candidate pair (kPairsPerGrain = 10: a grain has about 12-14
//                      neighbours within the Verlet skin, each pair counted
//                      once, with margin): CandidatePair in State::pairs and
//                      in the broadphase's scratch list, the broadphase's
//                      BodyPair, kMaxSubContacts SubContact slots and one int
//                      of the narrowphase;
//   per contact (kContactsPerGrain = 8: coordination numbers reach 8-10 in
//                      dense packings, i.e. 4-5 pairs per grain, with
//                      sub-contacts of faceted grains and wall contacts):
//                      Contact in State::contacts and in the list being
//                      compacted.
// Shapes (meshes) are shared by all grains and not counted. The estimate is
// compared with MemAvailable of /proc/meminfo (Linux); the specimen is
// refused when it needs more, or when N exceeds what an Index holds.
#pragma once

#include "core/available_memory.h"
#include "lab/lab_spec.h"

#include <cstdint>

namespace grainlab {

inline constexpr double kPairsPerGrain = 10;     // candidate pairs per grain (see above)
inline constexpr double kContactsPerGrain = 8;   // contacts per grain (see above)

// Bytes one grain needs during a run (the sum above).
double bytes_per_grain();

// Grains that fill the box at void ratio e with grains of mean volume v_mean (m^3).
double specimen_grain_count(const BoxSpec& box, double e, double v_mean);

// Throws InputError, naming the grain count and the memory, when `count`
// grains (for `what`, e.g. "the direct shear specimen") would not fit in
// `available` bytes (<= 0: unknown, only the count limit is checked) or in an Index.
void refuse_impossible_specimen(double count, double available, const BoxSpec& box, double mean_diameter,
                                const char* what);

// The specimen of `spec` at its target void ratio (the lab's e_min when the
// own indices are not measured yet: the most grains a target can ask), checked
// before anything long starts: generates the grain shapes into a scratch
// Model and calls refuse_impossible_specimen.
void check_specimen_fits(const LabSpec& spec);

}  // namespace grainlab
