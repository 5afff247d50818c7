// PreparationStore::keep_if_due (preparation_store.h).
#include "lab/preparation_store.h"

#include "core/error.h"

namespace grainlab {

void PreparationStore::keep_if_due(const DirectShearTest& test, const std::string& name,
                                   const DirectShearSpec& prepared, double wall_s, Stopwatch& since_kept,
                                   const std::function<std::string()>& stopped) {
  if (stop_requested()) {
    keep(test, name, prepared, wall_s);
    throw Stopped(stopped());
  }
  if (since_kept.seconds() < keep_interval_s) return;
  keep(test, name, prepared, wall_s);
  since_kept.reset();
}

}  // namespace grainlab
