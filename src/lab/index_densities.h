// The grains' own index void ratios (e_min, e_max), measured the way the
// specimen is prepared, so that a target Dr means the same for any grains.
//
// Box: L = W = box_diameters x d_max (the sieve's largest size; default 10),
// no gap between the halves, filled with as many grains as make a specimen
// height_diameters x d_max high at e = 0.7 (lab/specimen.h placement, at the
// run's seed).
//   e_min (densest): deposition under 100 g S with NO friction between grains
//     (nor with the lubricated walls), then compaction under the cap at the
//     consolidation stress (spec.consolidation.normal_stress), still without
//     friction, until the cap's stress is within 5 % and the kinetic energy is
//     small against the elastic (the protocol's compaction rest test). This is
//     as far as this method goes: no vibration, no cycles of load.
//   e_max (loosest): deposition with friction loose_friction (default 1.0,
//     kLoosestDepositionFriction) and no compaction; the
//     void ratio is measured under the grains' own weight (at 100 g S: the
//     stress at the floor is rho 100 g S h, about 1 MPa at S = 100 for 8
//     grains of height; rigid-grain friction does not depend on it, the
//     overlaps stay below 1e-2 d), with no cap: a cap at a light stress
//     would have to come to rest on a rough surface without compacting it.
// Void ratio: in the bulk (lab/packing_density.h), kBulkMarginDiameters
// (1.5) mean diameters from the side walls and the floor, and from the cap
// (dense) or 1.5 + 1 diameters below the highest grain top (loose: the
// surface is rough by about a diameter). The whole-box e (cap height) is
// also reported: it is larger, by the loose layer at the walls.
// Settling is capped at max_steps per preparation: frictionless faceted
// grains may ring without coming to rest; the result then says so
// (settled = false) and gives what was reached.
// A preparation of faceted grains can take hours; given a PreparationStore
// (lab/preparation_store.h) it is kept as "index_e_min_seed7" (or e_max) on
// an interval and on a stop request, and a later measurement goes on from
// where it was, to the same result bit for bit.
#pragma once

#include "lab/lab_spec.h"
#include "lab/preparation_search.h"
#include "lab/preparation_store.h"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace grainlab {

struct IndexDensityOptions {
  int seeds = 3;                  // preparations per index, seeds spec.seed, spec.seed + 1, ...
  double box_diameters = 10;      // box side in sieve d_max (the brief's minimum: 10)
  double height_diameters = 8;    // specimen height in d_max
  double loose_friction = kLoosestDepositionFriction;  // deposition friction of the loose preparation
  std::int64_t max_steps = 300000;  // per preparation (at most 400000, the protocol's own limit)
};

// One preparation.
struct IndexPreparation {
  std::uint64_t seed = 0;
  double friction = 0;         // deposition friction
  double void_ratio = 0;       // bulk
  double whole_void_ratio = 0; // (box volume below the cap or top) / solids - 1
  bool settled = false;        // came to rest within max_steps
  std::int64_t steps = 0;
  int grains = 0;
  double wall_s = 0;              // s of wall-clock time
};

struct IndexDensities {
  double e_min = 0, e_max = 0;              // means over the seeds (bulk)
  double e_min_spread = 0, e_max_spread = 0;  // max - min over the seeds
  std::vector<IndexPreparation> dense, loose;
  int grains = 0;                           // per preparation
  double box_length = 0, box_height = 0;    // m
  bool settled() const;                     // every preparation settled
};

// Progress lines ("dense seed 2: e = 0.584, 41000 steps").
using IndexProgress = std::function<void(const std::string&)>;
// Called after each preparation with those made so far (e_min, e_max not yet
// set), so that a caller can keep them: a preparation of faceted grains can
// take the better part of an hour.
using IndexPreparationDone = std::function<void(const IndexDensities& so_far)>;

// Measures e_min and e_max of the grains (spec.grains, spec.material,
// spec.consolidation.normal_stress, spec.numerics) as above. The
// preparations already in `done` (dense, then loose, in seed order: what an
// earlier, interrupted measurement passed to on_done) are kept, not made
// again; the caller is responsible for their having the same inputs.
IndexDensities measure_index_densities(const LabSpec& spec, const IndexDensityOptions& options,
                                       const IndexProgress& progress = {}, IndexDensities done = {},
                                       const IndexPreparationDone& on_done = {},
                                       PreparationStore* store = nullptr);

// The direct shear spec of one preparation of the index box (its seed, box
// and deposition friction); InputError for a box under 4 diameters.
LabSpec index_preparation_spec(const LabSpec& spec, const IndexDensityOptions& options, bool dense,
                                       std::uint64_t seed);

// The name a preparation is kept under: "index_e_min_seed7", "index_e_max_seed7".
std::string index_preparation_name(bool dense, std::uint64_t seed);

// One preparation of the index box: dense (friction 0, compacted) or loose.
// `progress` gets a line every 10,000 steps (phase, step, its status): a
// dense preparation of faceted grains can take hours. With a store, it goes
// on from what the store kept and keeps what it does (above).
IndexPreparation prepare_index_specimen(const LabSpec& spec, const IndexDensityOptions& options,
                                        bool dense, std::uint64_t seed, const IndexProgress& progress = {},
                                        PreparationStore* store = nullptr);

}  // namespace grainlab
