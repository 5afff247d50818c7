// PreparationStore::keep_if_due (preparation_store.h).
#include "lab/preparation_store.h"

#include "core/error.h"

namespace grainlab {

void PreparationStore::keep_if_due(const SpecimenPreparation& preparation, const std::string& name,
                                   const LabSpec& prepared, double wall_s, Stopwatch& since_kept,
                                   const std::function<std::string()>& stopped) {
  if (stop_requested()) {
    keep(preparation, name, prepared, wall_s);
    throw Stopped(stopped());
  }
  if (since_kept.seconds() < keep_interval_s) return;
  keep(preparation, name, prepared, wall_s);
  since_kept.reset();
}

}  // namespace grainlab
