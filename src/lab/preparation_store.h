// Where a preparation in progress is kept, so that a run stopped or killed
// while it prepares its specimen goes on from where it was: the
// preparations of the grains' own index densities (lab/index_densities.h)
// and the trials of the search for the deposition friction
// (lab/preparation_search.h), each of which can take hours with faceted
// grains. A preparation is deterministic, so going on from what was kept
// gives the result of an uninterrupted one, to the bit.
// apps keeps them as checkpoint files in the run folder (io/kept_preparations.h).
#pragma once

#include "core/step_pacer.h"
#include "core/timer.h"
#include "lab/lab_spec.h"

#include <functional>
#include <limits>
#include <string>

namespace grainlab {

class SpecimenPreparation;

class PreparationStore {
 public:
  virtual ~PreparationStore() = default;
  // `name` names the preparation ("index_e_min_seed7", "trial_friction_0.02990000");
  // `prepared` is its own spec (seed, box, deposition friction...): what a
  // kept preparation must match.
  // Restores `preparation` (State, then its own bytes) from what was kept of it, if
  // that fits `prepared`; returns the wall seconds it had run, or a
  // negative number if nothing was restored.
  virtual double restore(SpecimenPreparation& preparation, const std::string& name, const LabSpec& prepared) = 0;
  // Keeps the preparation as it is now, after `wall_s` seconds in all.
  virtual void keep(const SpecimenPreparation& preparation, const std::string& name, const LabSpec& prepared,
                    double wall_s) = 0;
  // What was kept of it can go.
  virtual void drop(const std::string& name) = 0;
  // True when the caller wants the preparation to stop (a signal): it is
  // kept and Stopped (core/error.h) thrown.
  virtual bool stop_requested() const { return false; }
  double keep_interval_s = 600;  // s of wall-clock time between keeps
  // s of wall-clock time between looks at stop_requested(): a preparation
  // steps in batches sized to it (core/step_pacer.h), of 100 steps at most,
  // so a stop signal is seen within a fraction of a second even where 100
  // steps take seconds. Infinity: a batch is always 100 steps (tests that stop
  // at a given step).
  double stop_check_period_s = 0.25;

  // Between batches of a preparation's steps: when a stop is asked for,
  // keeps it and throws Stopped(stopped()); else keeps it if
  // keep_interval_s has passed on `since_kept` (then reset). `wall_s` is
  // its wall seconds in all.
  void keep_if_due(const SpecimenPreparation& preparation, const std::string& name, const LabSpec& prepared,
                   double wall_s, Stopwatch& since_kept, const std::function<std::string()>& stopped);
};

// The pacer of the batches of steps of a preparation kept in `store` (see
// stop_check_period_s); batches of 100 steps when there is no store.
inline StepPacer batch_pacer(const PreparationStore* store) {
  constexpr int kMaxBatch = 100;
  return StepPacer(kMaxBatch, store ? store->stop_check_period_s : std::numeric_limits<double>::infinity(), kMaxBatch);
}

}  // namespace grainlab
