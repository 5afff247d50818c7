// Specimen preparation: grains placed on a loose lattice, deposited under a
// strong gravity with a low friction, then compacted under a cap.
//
// Placement: as many grains as fill the box volume L W H at the target void
// ratio e (N = L W H / ((1 + e) V_mean)), on a square lattice of pitch
// 2.1 x the largest bounding radius, layer by layer from the floor, each of
// a random shape and orientation with a tiny random velocity (seeded).
//
// Deposition: gravity 100 g times the density scale S (the grains' weight
// then accelerates their S-times heavier inertial mass at 100 g: a numerical
// step, not physics) and the deposition friction (lower: denser). Settled
// when the kinetic energy is below the work of lifting every grain by a
// thousandth of its diameter against that gravity (inertial masses on both
// sides); the compaction that follows finishes the settling under the cap.
#pragma once

#include "lab/grain_library.h"

#include "dynamics/world.h"
#include "lab/lab_spec.h"

namespace grainlab {

inline constexpr double kDepositionGravity = 100;  // g while raining
inline constexpr double kStandardGravity = 9.81;   // m/s^2

// What the placement made.
struct Specimen {
  double solid_volume = 0;   // m^3
  double mean_diameter = 0;  // m, volume-equivalent, of the shapes
  double mean_mass = 0;      // kg, true mass
  double fill_top = 0;       // m, top of the loose fill
  GrainRepresentation representation;  // how the shapes are collided
  struct Scan {                        // a specimen from a segmented scan (scanned_specimen.h)
    int grains = 0;                    // placed (0: not a scan)
    int border_dropped = 0;            // left out: touching the image border
    double spread = 1;                 // factor on the positions about the scan's centre
    double void_ratio = 0;             // of the scanned grains' bounding box: V_box / V_solid - 1
  } scan;
};

// Adds the grain shapes and the grains (material `grain_material`) of `spec`
// to w on the loose lattice inside the box centred on x = y = 0.
Specimen place_loose_specimen(World& w, const LabSpec& spec, Index grain_material);

// The phase settings of deposition (gravity 100 g S) or of compaction (the
// Model's gravity), both with the deposition friction on the grain material.
PhaseOverrides deposition_overrides(const World& w, const LabSpec& spec, Index grain_material);
PhaseOverrides compaction_overrides(const LabSpec& spec, Index grain_material);

// Deposition's settled test (above).
bool deposit_settled(const World& w, const Specimen& s);

// Puts plane wall `cap` just above the highest grain (5 % of a diameter).
void lower_cap_onto_grains(World& w, Index cap, double mean_diameter);

}  // namespace grainlab
