// The time-step guard and the thread choice of World::step (step_guard.h).
#include "dynamics/step_guard.h"

#include "core/error.h"
#include "core/parallel.h"
#include "dynamics/time_step.h"

#include <cmath>

namespace grainlab {

void require_stable_step(const Model& model, double expected_overlap_fraction, double dt) {
  if (!(dt > 0 && std::isfinite(dt))) input_error("time step {} s must be positive", dt);
  const TimeStepEstimate est = critical_time_step(model, expected_overlap_fraction);
  if (dt > est.critical) {
    const double ratio = dt / est.critical;
    input_error(
        "time step {:.3g} s is above the critical step {:.3g} s of this model (set by grain {} "
        "with contact stiffness {:.3g} N/m at an overlap of {:.2g} of its radius, damping ratio "
        "{:.2f}): the run would explode. Use a time step of at most {:.3g} s (about a tenth of the critical step is "
        "accurate), or scale the density by at least {:.3g} (numerics.density_scaling) for a "
        "quasi-static test",
        dt, est.critical, est.limiting_body, est.stiffness, expected_overlap_fraction, est.damping_ratio,
        est.critical, ratio * ratio);
  }
}

int choose_step_threads(const WorldSettings& settings, ThreadTuner& tuner) {
  if (settings.threads > 0) return settings.threads;
  if (tuner.max_threads() != resolve_threads(0)) tuner = ThreadTuner(resolve_threads(0), settings.thread_tuning);
  return tuner.threads();
}

}  // namespace grainlab
