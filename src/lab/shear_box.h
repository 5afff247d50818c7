// The walls of a direct shear box (rigid, lubricated), for a box of inner
// length L (x, the shear direction), width W (y) and specimen height H:
//   floor        plane z = 0, normal +z
//   lower half   four slabs around the box for z < H/2 - gap/2 (fixed)
//   upper half   four slabs for z > H/2 + gap/2 up to the fill height + t
//   cap          plane, normal -z, at the fill height + t/2
// Slabs are t = 2.5 mm thick (thicker than the largest shear displacement of
// the default box) so that no opening appears as the halves slide.
#pragma once

#include "dynamics/world.h"
#include "lab/direct_shear_spec.h"

namespace grainlab {

inline constexpr double kShearBoxSlab = 2.5e-3;  // m, t: thickness of the side slabs

// Walls by role, in the order build_shear_box adds them (World wall indices
// when the box is built into an empty World).
enum ShearBoxWall : Index { Floor = 0, LowerXm, LowerXp, LowerYm, LowerYp, UpperXm, UpperXp, UpperYm, UpperYp, Cap, ShearBoxWallCount };

// Adds the box's walls to `w` (material `material`); fill_top (m) is the top of the loose fill.
void build_shear_box(World& w, const BoxSpec& box, double fill_top, Index material);

}  // namespace grainlab
