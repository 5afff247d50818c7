// Deposition friction by bisection (method in preparation_search.h).
#include "lab/preparation_search.h"

#include "core/error.h"
#include "core/timer.h"
#include "lab/deposition_friction.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fmt/format.h>
#include <limits>
#include <optional>

namespace grainlab {

namespace {

constexpr double kU = 0.1;  // u = mu / (mu + kU)

double to_u(double mu) { return mu / (mu + kU); }
double to_mu(double u) { return kU * u / (1 - u); }

// e of a trial as the target judges it, and its Dr on the target's indices.
double judged_void_ratio(const LabSpec& spec, const SpecimenPreparation& t) {
  return spec.targets_own_indices() ? t.achieved_bulk_void_ratio() : t.achieved_void_ratio();
}

double judged_relative_density(const LabSpec& spec, double e) {
  const auto& s = spec.specimen;
  if (spec.targets_own_indices()) return (s.own_e_max - e) / (s.own_e_max - s.own_e_min);
  return (s.e_max - e) / (s.e_max - s.e_min);
}

}  // namespace

std::string trial_preparation_name(double mu) { return fmt::format("trial_friction_{:.8f}", mu); }

std::unique_ptr<SpecimenPreparation> trial_preparation(const LabSpec& spec, double mu, PreparationTrial& out,
                                                       PreparationStore* store,
                                                       const std::function<void(const std::string&)>& said) {
  LabSpec s = spec;
  s.specimen.deposition_friction = mu;
  Stopwatch clock, since_kept;
  auto t = std::make_unique<SpecimenPreparation>(s);
  t->accept_any_density();
  const std::string name = trial_preparation_name(mu);
  const double kept_s = store ? store->restore(*t, name, s) : -1.0;
  const double earlier_s = std::max(0.0, kept_s);
  if (kept_s >= 0 && said)
    said(fmt::format("  trial at deposition friction {:.4f}: going on from step {} ({} phase), kept after {:.0f} s", mu,
                     t->world().state.step, t->phase_name(), kept_s));
  bool stepped = false;
  std::int64_t next_line = (t->world().state.step / 10000 + 1) * 10000;
  StepPacer pacer = batch_pacer(store);  // a stop is seen within about a quarter second
  try {
    while (t->phase() < PreparationPhase::Consolidate) {
      const std::int64_t before = t->world().state.step;
      t->advance(pacer.next());
      pacer.done(t->world().state.step - before);
      stepped = true;
      if (said && t->world().state.step >= next_line) {  // a trial of angular grains runs for hours
        next_line += 10000;
        said(fmt::format("  trial at deposition friction {:.4f}: step {}, {} phase, {:.0f} s: {}", mu,
                         t->world().state.step, t->phase_name(), earlier_s + clock.seconds(), t->status_line()));
      }
      if (store)
        store->keep_if_due(*t, name, s, earlier_s + clock.seconds(), since_kept, [&] {
          return fmt::format("the trial preparation at deposition friction {:.4f} was stopped at step {} and kept "
                             "(the run goes on from there)",
                             mu, t->world().state.step);
        });
    }
  } catch (const RunError&) {
    if (store) store->drop(name);
    throw;
  }
  if (store && stepped) store->keep(*t, name, s, earlier_s + clock.seconds());  // finished: taken back at once
  out.friction = mu;
  out.void_ratio = judged_void_ratio(spec, *t);
  out.relative_density = judged_relative_density(spec, out.void_ratio);
  out.steps = t->world().state.step;
  out.wall_s = earlier_s + clock.seconds();
  return t;
}

Preparation prepare_to_target(const LabSpec& spec, const PreparationSearchOptions& o,
                              const PreparationProgress& progress) {
  if (spec.targets_own_indices() && !spec.own_indices_known())
    input_error("the preparation search needs the grains' own index void ratios for a Dr target on them: set "
                "specimen.own_e_min/own_e_max (`grainlab grains index`), or let `grainlab run` measure them");
  const double target = spec.target_void_ratio();
  const bool own = spec.targets_own_indices();
  const auto hit = [&](const PreparationTrial& t) {
    return own ? std::abs(t.relative_density - spec.specimen.relative_density) <= spec.specimen.relative_density_tolerance
               : std::abs(t.void_ratio - target) <= spec.specimen.tolerance;
  };
  const std::string goal =
      own ? fmt::format("Dr {:.2f} +- {:.2f} on the grains' own indices (bulk e = {:.3f})",
                        spec.specimen.relative_density, spec.specimen.relative_density_tolerance, target)
          : fmt::format("e = {:.3f} +- {:.3f}", target, spec.specimen.tolerance);

  Preparation p;
  double u_lo = 0, u_hi = to_u(o.max_friction);
  const double u_index = to_u(std::min(kLoosestDepositionFriction, o.max_friction));  // where e_max was measured
  std::optional<double> e_lo, e_hi;  // measured e at the bracket's ends
  // The first trial at exactly the friction lab/deposition_friction.h gives
  // (a grain class's measured one is tried as it is), the next ones in u.
  double mu = std::min(first_deposition_friction(spec), o.max_friction);
  double u = to_u(mu);
  double best_miss = std::numeric_limits<double>::infinity();
  std::string why;
  const TrialPreparation run_trial =
      o.trial ? o.trial : [&](const LabSpec& s, double mu, PreparationTrial& out) {
        return trial_preparation(s, mu, out, o.store, progress);
      };
  double best_e = NAN;
  for (int k = 0; k < o.max_trials; ++k) {
    PreparationTrial trial;
    std::unique_ptr<SpecimenPreparation> t;
    Stopwatch clock;
    try {
      t = run_trial(spec, mu, trial);
    } catch (const RunError& e) {
      trial = PreparationTrial{mu, NAN, NAN, 0, clock.seconds(), e.what()};
    }
    p.trials.push_back(trial);
    if (!trial.error.empty()) {
      if (progress)
        progress(fmt::format("trial {}: deposition friction {:.4f} failed ({:.0f} s): {}", k + 1, trial.friction,
                             trial.wall_s, trial.error));
      const double step = 0.1 * (u_hi - u_lo);
      u = u < 0.5 * (u_lo + u_hi) ? u + step : u - step;
      mu = to_mu(u);
      continue;
    }
    if (progress)
      progress(fmt::format("trial {}: deposition friction {:.4f} -> e = {:.4f}{} ({} steps, {:.0f} s)", k + 1,
                           trial.friction, trial.void_ratio,
                           std::isnan(trial.relative_density) ? "" : fmt::format(", Dr {:.3f}", trial.relative_density),
                           trial.steps, trial.wall_s));
    if (hit(trial)) {
      p.specimen = std::move(t);
      p.friction = trial.friction;
      return p;
    }
    const double miss = std::abs(trial.void_ratio - target);
    if (miss < best_miss) best_miss = miss, best_e = trial.void_ratio;
    if (trial.void_ratio < target) u_lo = u, e_lo = trial.void_ratio;
    else u_hi = u, e_hi = trial.void_ratio;
    // The ends: frictionless still too loose, or the loosest still too dense.
    if (u == 0 && trial.void_ratio > target) {
      why = "frictionless deposition and compaction, the densest this preparation makes, is still looser than "
            "the target";
      break;
    }
    if (u >= to_u(o.max_friction) && trial.void_ratio < target) {
      why = fmt::format("deposition at friction {:g}, the loosest this search tries, is still denser than the "
                        "target (the compaction under the cap packs it)",
                        o.max_friction);
      break;
    }
    const double u_max = to_u(o.max_friction);
    if (e_lo && e_hi) {
      const double f = (target - *e_lo) / (*e_hi - *e_lo);
      u = u_lo + std::clamp(f, 0.1, 0.9) * (u_hi - u_lo);
    } else if (e_hi) {  // every trial too loose: towards frictionless
      u = u_hi <= 0.5 * u_max ? 0 : 0.5 * u_hi;
    } else if (u_lo < u_index) {  // every trial too dense: towards the e_max friction first
      u = u_lo >= 0.5 * u_index ? u_index : 0.5 * (u_lo + u_index);
    } else {  // the e_max friction too: the loosest end
      u = u_max;
    }
    mu = to_mu(u);
  }
  if (why.empty() && std::isnan(best_e))
    why = "every trial failed (each trial's error is listed): a phase did not come to rest";
  if (why.empty()) why = fmt::format("{} trials did not land within the tolerance (the packing's scatter at a "
                                     "given friction may be as large as the tolerance)",
                                     p.trials.size());
  std::string list;
  for (const PreparationTrial& t : p.trials)
    list += t.error.empty() ? fmt::format(" mu {:.4f} -> e {:.4f};", t.friction, t.void_ratio)
                            : fmt::format(" mu {:.4f} failed ({});", t.friction, t.error);
  throw RunError(fmt::format(
      "specimen preparation could not reach {}: {}. Trials:{} closest e = {}. To fix: set a reachable "
      "target (specimen.relative_density or specimen.void_ratio), allow a wider specimen.{}, or make the box "
      "larger (a small box's walls loosen the packing)",
      goal, why, list, std::isnan(best_e) ? std::string("none") : fmt::format("{:.4f}", best_e),
      own ? "relative_density_tolerance" : "tolerance"));
}

}  // namespace grainlab
