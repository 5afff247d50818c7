// The grains' own index void ratios (method in index_densities.h).
#include "lab/index_densities.h"

#include "core/error.h"
#include "core/timer.h"
#include "lab/preparation.h"
#include "lab/packing_density.h"

#include <algorithm>
#include <fmt/format.h>

namespace grainlab {

bool IndexDensities::settled() const {
  for (const auto* list : {&dense, &loose})
    for (const IndexPreparation& p : *list)
      if (!p.settled) return false;
  return true;
}

LabSpec index_preparation_spec(const LabSpec& spec, const IndexDensityOptions& o, bool dense,
                                       std::uint64_t seed) {
  if (o.box_diameters < 4 || o.height_diameters < 4)
    input_error("index densities: a box of {} x {} grain diameters is too small to have a bulk away from the "
                "walls; use at least 4 (10 or more for the material's index voids)",
                o.box_diameters, o.height_diameters);
  LabSpec s = spec;
  s.seed = seed;
  s.box.length = s.box.width = o.box_diameters * spec.grains.d_max;
  s.box.height = o.height_diameters * spec.grains.d_max;
  s.box.gap = 0;
  s.specimen.void_ratio = 0.7;  // only sets the grain count
  s.specimen.indices = "lab";
  s.specimen.deposition_friction = dense ? 0.0 : o.loose_friction;
  return s;
}

std::string index_preparation_name(bool dense, std::uint64_t seed) {
  return fmt::format("index_{}_seed{}", dense ? "e_min" : "e_max", seed);
}

IndexPreparation prepare_index_specimen(const LabSpec& spec, const IndexDensityOptions& o, bool dense,
                                        std::uint64_t seed, const IndexProgress& progress,
                                        PreparationStore* store) {
  const LabSpec s = index_preparation_spec(spec, o, dense, seed);
  SpecimenPreparation t(s);
  t.accept_any_density();
  const char* name = dense ? "e_min" : "e_max";
  const std::string kept = index_preparation_name(dense, seed);
  World& w = t.world();
  double earlier_s = 0;  // wall seconds of earlier sittings
  if (store) {
    earlier_s = store->restore(t, kept, s);
    if (earlier_s >= 0 && progress)
      progress(fmt::format("  {} seed {}: going on from step {} ({} phase), kept after {:.0f} s", name, seed,
                           w.state.step, t.phase_name(), earlier_s));
    earlier_s = std::max(earlier_s, 0.0);
  }
  Stopwatch clock, since_kept, since_line;
  const PreparationPhase goal = dense ? PreparationPhase::Consolidate : PreparationPhase::Compact;
  const std::int64_t cap = std::min<std::int64_t>(o.max_steps, 399000);
  std::int64_t next_line = (w.state.step / 10000 + 1) * 10000;
  StepPacer pacer = batch_pacer(store);  // a stop is seen within about a quarter second
  while (t.phase() < goal && w.state.step - t.phase_step(t.phase()) < cap) {
    const std::int64_t before = w.state.step;
    t.advance(pacer.next());
    pacer.done(w.state.step - before);
    if (store)
      store->keep_if_due(t, kept, s, earlier_s + clock.seconds(), since_kept, [&] {
        return fmt::format("the {} preparation of seed {} was stopped at step {} and kept (the run goes on from "
                           "there)",
                           name, seed, w.state.step);
      });
    // A line every 10,000 steps, or every minute where steps are slow (a
    // concave grain's index box runs about ten steps a second).
    if (!progress || (w.state.step < next_line && since_line.seconds() < 60)) continue;
    next_line = (w.state.step / 10000 + 1) * 10000;
    since_line.reset();
    progress(fmt::format("  {} seed {}: step {}, {} phase, {:.0f} s: {}", name, seed, w.state.step, t.phase_name(),
                         earlier_s + clock.seconds(), t.status_line()));
  }

  IndexPreparation p;
  p.seed = seed;
  p.friction = s.specimen.deposition_friction;
  p.settled = t.phase() >= goal;
  p.steps = w.state.step;
  p.grains = static_cast<int>(w.model.bodies.size());
  const double d = t.mean_diameter(), L = s.box.length;
  double top = 0;  // the cap, or the highest grain top when there is none yet
  if (dense && t.phase() >= PreparationPhase::Compact) {
    top = w.state.walls[Cap].x.z();
  } else {
    for (std::size_t i = 0; i < w.model.bodies.size(); ++i)
      top = std::max(top, w.state.bodies[i].x.z() + w.model.bodies[i].bounding_radius);
  }
  const Region r = bulk_region(L, L, dense ? top : top - d, d);
  p.void_ratio = void_ratio_in_region(w.model, w.state, r.lo, r.hi);
  p.whole_void_ratio = L * L * top / t.solid_volume() - 1;
  p.wall_s = earlier_s + clock.seconds();
  return p;
}

IndexDensities measure_index_densities(const LabSpec& spec, const IndexDensityOptions& o,
                                       const IndexProgress& progress, IndexDensities done,
                                       const IndexPreparationDone& on_done, PreparationStore* store) {
  if (o.seeds < 1) input_error("index densities: seeds = {}; use at least 1 (3 to see the spread)", o.seeds);
  IndexDensities r = std::move(done);
  if (!r.loose.empty() && r.dense.size() < static_cast<std::size_t>(o.seeds)) r.loose.clear();  // out of order
  r.dense.resize(std::min<std::size_t>(r.dense.size(), o.seeds));
  r.loose.resize(std::min<std::size_t>(r.loose.size(), o.seeds));
  r.box_length = o.box_diameters * spec.grains.d_max;
  r.box_height = o.height_diameters * spec.grains.d_max;
  for (int dense = 1; dense >= 0; --dense) {
    auto& list = dense ? r.dense : r.loose;
    for (int k = static_cast<int>(list.size()); k < o.seeds; ++k) {
      list.push_back(prepare_index_specimen(spec, o, dense, spec.seed + k, progress, store));
      const IndexPreparation& p = list.back();
      if (on_done) on_done(r);
      if (store) store->drop(index_preparation_name(dense, spec.seed + k));  // in r now
      if (progress)
        progress(fmt::format("{} (friction {:g}) seed {}: bulk e = {:.4f}, whole-box e = {:.4f}, {} steps, "
                             "{:.0f} s{}",
                             dense ? "e_min" : "e_max", p.friction, p.seed, p.void_ratio, p.whole_void_ratio,
                             p.steps, p.wall_s, p.settled ? "" : " (NOT settled: step cap reached)"));
    }
    double sum = 0, lo = list.front().void_ratio, hi = lo;
    for (const IndexPreparation& p : list) {
      sum += p.void_ratio;
      lo = std::min(lo, p.void_ratio), hi = std::max(hi, p.void_ratio);
    }
    (dense ? r.e_min : r.e_max) = sum / list.size();
    (dense ? r.e_min_spread : r.e_max_spread) = hi - lo;
  }
  r.grains = r.dense.front().grains;
  return r;
}

}  // namespace grainlab
