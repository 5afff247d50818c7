// Where a preparation in progress is kept, so that a run stopped or killed
// while it prepares its specimen goes on from where it was: the
// preparations of the grains' own index densities (lab/index_densities.h)
// and the trials of the search for the deposition friction
// (lab/preparation_search.h), each of which can take hours with faceted
// grains. A preparation is deterministic, so going on from what was kept
// gives the result of an uninterrupted one, to the bit.
// apps keeps them as checkpoint files in the run folder (io/kept_preparations.h).
#pragma once

#include "core/timer.h"
#include "lab/lab_spec.h"

#include <functional>
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

  // Between batches of a preparation's steps: when a stop is asked for,
  // keeps it and throws Stopped(stopped()); else keeps it if
  // keep_interval_s has passed on `since_kept` (then reset). `wall_s` is
  // its wall seconds in all.
  void keep_if_due(const SpecimenPreparation& preparation, const std::string& name, const LabSpec& prepared,
                   double wall_s, Stopwatch& since_kept, const std::function<std::string()>& stopped);
};

}  // namespace grainlab
