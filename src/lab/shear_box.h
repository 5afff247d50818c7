// The walls of a direct shear box (rigid, lubricated), for a box of inner
// length L (x, the shear direction), width W (y) and specimen height H:
//   floor        plane z = 0, normal +z
//   lower half   four slabs around the box for z < H/2 - gap/2 (fixed)
//   upper half   four slabs for z > H/2 + gap/2 up to the fill height + t
//   cap          plane, normal -z, at the fill height + t/2
// Slabs are t = 2.5 mm thick (thicker than the largest shear displacement of
// the default box) so that no opening appears as the halves slide.
//
// The gap is closed while the specimen is made: the upper half is built
// resting on the lower one (its slabs' bottom at H/2 - gap/2, the whole half
// gap lower than above) and open_shear_box_gap raises it by the gap when the
// shear begins, as a laboratory opens the gap after consolidation. A grain
// thinner than the gap cannot leave the box through it while grains fall and
// bounce (session 17 lost a 0.32 mm flat grain through the 0.30 mm gap that
// way). Raising frictionless slabs drags no grain.
#pragma once

#include "dynamics/world.h"
#include "lab/lab_spec.h"

namespace grainlab {

inline constexpr double kShearBoxSlab = 2.5e-3;  // m, t: thickness of the side slabs

// Walls by role, in the order build_shear_box adds them (World wall indices
// when the box is built into an empty World).
enum ShearBoxWall : Index { Floor = 0, LowerXm, LowerXp, LowerYm, LowerYp, UpperXm, UpperXp, UpperYm, UpperYp, Cap };

// Adds the box's walls to `w` (material `material`), the gap closed; fill_top
// (m) is the top of the loose fill.
void build_shear_box(World& w, const BoxSpec& box, double fill_top, Index material);

// Raises the upper half's slabs so that their bottom is at H/2 + gap/2 (the
// gap open). Sets the height, so it may be called again (and leaves a box
// built open by an older grainlab, restored from its checkpoint, as it is).
void open_shear_box_gap(World& w, const BoxSpec& box);

// The first grain whose centre lies beyond the outer face of a side slab,
// below the floor or above the cap: a grain that left the box. -1: none.
Index grain_outside_shear_box(const World& w);

}  // namespace grainlab
