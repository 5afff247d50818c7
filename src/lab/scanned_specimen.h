// A specimen rebuilt from a segmented CT scan (issue 12 item 4): every grain
// of grains.scan placed where it was scanned, centred in the box on x and y
// and lowered onto the floor, then consolidated as the paper did (no
// deposition, no compaction).
//
// Segmented neighbours can overlap by a fraction of a voxel where their
// meshes were smoothed apart from one boundary; a Hertz contact at such a
// depth would throw them apart. So the positions (not the grains) are spread
// about the scan's centre by the least factor of kScanSpreads that leaves no
// overlap deeper than kScanOverlap of the mean diameter; consolidation closes
// those gaps again. The factor is reported.
#pragma once

#include "dynamics/world.h"
#include "lab/lab_spec.h"
#include "lab/specimen.h"

namespace grainlab {

inline constexpr double kScanSpreads[] = {1.0, 1.002, 1.005, 1.01, 1.02, 1.05};
inline constexpr double kScanOverlap = 1e-3;

// Adds the scan's grains (shapes by grains.representation) to w. Throws
// InputError when the scanned grains do not fit the box (with the box size
// they need) or still overlap at the largest spread.
Specimen place_scanned_specimen(World& w, const LabSpec& spec, Index grain_material);

}  // namespace grainlab
