// Preparation that reaches its target: the deposition friction chosen by
// bisection over trial preparations of the run's own box.
//
// Each trial is the direct shear protocol's preparation (lab/specimen.h:
// placement, deposition under 100 g S, compaction under the cap at the
// consolidation stress), with deposition friction mu, at the run's seed:
// the trial that lands on the target IS the specimen (no extrapolation from
// a smaller box), and the run continues from it.
// The void ratio e(mu) grows with mu (friction holds the grains apart while
// they settle): mu = 0 gives the densest specimen, mu_max (5) the loosest.
// The search keeps a bracket [mu_lo, mu_hi] with e(mu_lo) < e_target <
// e(mu_hi) and picks the next mu by linear interpolation of e in
// u = mu / (mu + 0.1) (e changes most between mu = 0 and 0.3; in u the curve
// is nearly straight), kept within the inner 80 % of the bracket so that it
// always shrinks; an end not tried yet is bisected, the loose one in two
// stages: up to the e_max preparation's friction (1.0), and only when that
// is still too dense to mu_max. The first guess is
// first_deposition_friction (lab/deposition_friction.h): the grain class's
// measured friction for a target at its measured Dr, else e linear in u
// between the own indices e_min (u = 0) and e_max (u at friction 1.0) when
// they are known, else mu = 0.12.
// Accepted: |Dr - Dr_target| <= relative_density_tolerance on own indices
// (bulk e), else |e - e_target| <= specimen.tolerance (whole specimen).
// Stops with RunError (the trials, the closest, why, how to fix) when mu = 0
// is still too loose, mu_max still too dense, or max_trials are spent.
// A trial that fails (RunError: a phase that did not come to rest) is a
// failed trial, not the end: it is listed with its error, counts against
// max_trials, and the next trial moves a tenth of the bracket towards the
// bracket's middle (another friction, another packing).
#pragma once

#include "lab/preparation.h"
#include "lab/preparation_store.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace grainlab {

// The deposition friction of the e_max preparation (lab/index_densities.h),
// and where the search's first guess puts e_max. Until the
// critical step included the contact damping (dynamics/time_step.h),
// deposition at friction 0.6 or 1.0 never came to rest (beads spun up to
// 3e3 rad/s) and this was 0.4, where glass beads gave e_max = 0.626, barely
// above e_min. Now glass beads at friction 1.0 come to rest in ~3600 steps
// (550 beads, 8 d_max box) at bulk e_max = 0.715, a random loose packing.
inline constexpr double kLoosestDepositionFriction = 1.0;

// The loosest end of the search: higher than the e_max friction, because a
// specimen is compacted under the cap at the consolidation stress and the
// e_max packing is not (a loose deposition partly collapses under the
// load). Measured 2026-12-05 (bench/bench_preparation_range, the demo's box
// of glass beads, 100 kPa; own e_max 0.750 at friction 1.0): deposition at
// friction 1.0 then compaction gave Dr 0.26 on the own indices, 1.72 gave
// 0.21, 5 gave 0.10; so with the end at 1.0 beads could not be prepared at
// Dr 0.2. As moist tamping does in the laboratory, the search may make a
// specimen looser than the index e_max (Dr < 0 is possible).
inline constexpr double kLoosestSearchFriction = 5.0;

struct PreparationTrial {
  double friction = 0;          // deposition friction tried
  double void_ratio = 0;        // the judged void ratio: bulk (own indices) or whole specimen; NaN if failed
  double relative_density = 0;  // on the target's indices (NaN for a void-ratio target without indices)
  std::int64_t steps = 0;
  double wall_s = 0;            // s of wall-clock time
  std::string error;            // why the trial failed (a phase that did not come to rest); empty if it did not
};

// One trial preparation at deposition friction mu: the preparation after
// compaction, with `out` filled in; throws RunError if it fails.
using TrialPreparation = std::function<std::unique_ptr<SpecimenPreparation>(const LabSpec& spec, double mu,
                                                                              PreparationTrial& out)>;

struct PreparationSearchOptions {
  double max_friction = kLoosestSearchFriction;  // the loosest end of the search
  int max_trials = 8;
  TrialPreparation trial;  // empty: trial_preparation below (tests put a model of e(mu) here)
  PreparationStore* store = nullptr;  // keeps the trials (trial_preparation below)
};

struct Preparation {
  std::unique_ptr<SpecimenPreparation> specimen;  // compacted at the chosen friction (phase Consolidate)
  std::vector<PreparationTrial> trials;
  double friction = 0;                    // chosen
};

using PreparationProgress = std::function<void(const std::string&)>;

// One trial preparation at deposition friction mu: the preparation after compaction.
// With a store it goes on from what the store kept of it (a finished one is
// taken back at once), keeps it every store->keep_interval_s and when it
// ends, and when the store asks to stop (every 100 steps) keeps it and
// throws Stopped (core/error.h). A trial that fails is dropped.
// `said` (may be empty) gets a line when the trial goes on from a kept one,
// and one every 10,000 steps (step, phase, wall seconds, the test's status).
std::unique_ptr<SpecimenPreparation> trial_preparation(const LabSpec& spec, double mu, PreparationTrial& out,
                                                       PreparationStore* store = nullptr,
                                                       const std::function<void(const std::string&)>& said = {});
// The name a trial is kept under: "trial_friction_0.02990000".
std::string trial_preparation_name(double mu);

// The search above. spec.specimen.deposition_friction is ignored (the
// search chooses it); own-index targets need the own indices known.
Preparation prepare_to_target(const LabSpec& spec, const PreparationSearchOptions& options = {},
                              const PreparationProgress& progress = {});

}  // namespace grainlab
