// What World::step settles before its phases run: that the time step is
// stable for this model (checked once per new dt), and how many threads the
// step runs on (the World's own count, or its tuner's). Kept apart from the
// phases so that World::step reads as the recipe of its phases.
#pragma once

#include "core/thread_tuner.h"
#include "dynamics/model.h"
#include "dynamics/world_settings.h"

namespace grainlab {

// Throws InputError unless 0 < dt <= the critical step of `model`
// (time_step.h), with a message that says how to fix the run.
void require_stable_step(const Model& model, double expected_overlap_fraction, double dt);

// The thread count of this step: settings.threads, or, when it is 0, the
// tuner's (core/thread_tuner.h; remade when the machine's count changed).
int choose_step_threads(const WorldSettings& settings, ThreadTuner& tuner);

}  // namespace grainlab
