// Grain count and memory of a specimen (rules in specimen_budget.h).
#include "lab/specimen_budget.h"

#include "collision/aabb.h"
#include "collision/broadphase.h"
#include "core/error.h"
#include "dynamics/model.h"
#include "dynamics/state.h"
#include "geometry/mass_properties.h"
#include "lab/grain_library.h"

#include <cmath>
#include <fstream>
#include <limits>
#include <numbers>
#include <vector>
#include <algorithm>
#include <sstream>
#include <string>

namespace grainlab {

double bytes_per_grain() {
  const double once = sizeof(BodyModel) + 2 * sizeof(BodyState) + 4 * sizeof(Vec3) + sizeof(Mat3) +
                      sizeof(Aabb) + sizeof(double);
  const double pair = 2 * sizeof(CandidatePair) + sizeof(BodyPair) + kMaxSubContacts * sizeof(SubContact) +
                      sizeof(int);
  const double contact = 2 * sizeof(Contact);
  return once + kPairsPerGrain * pair + kContactsPerGrain * contact;
}

double specimen_grain_count(const BoxSpec& box, double e, double v_mean) {
  return box.length * box.width * box.height / ((1 + e) * v_mean);
}

void refuse_impossible_specimen(double count, double available, const BoxSpec& box, double mean_diameter,
                                const char* what) {
  const double need = count * bytes_per_grain();
  const bool too_many = count > static_cast<double>(std::numeric_limits<Index>::max());
  const bool too_big = available > 0 && need > available;
  if (!too_many && !too_big) return;
  // The largest cube of this height that fits (the count grows with L W).
  const double fits = std::min(available > 0 ? available / bytes_per_grain() : count,
                               static_cast<double>(std::numeric_limits<Index>::max()));
  const double side = std::sqrt(box.length * box.width * fits / count);
  input_error("{}: a box of {:.4g} x {:.4g} x {:.4g} mm needs about {:.3g} grains of {:.3f} mm, which "
              "would take about {:.3g} GB of memory ({:.0f} bytes per grain){}{}. Make the box smaller "
              "(at this height, at most about {:.3g} x {:.3g} mm fits) or the grains larger.",
              what, box.length * 1e3, box.width * 1e3, box.height * 1e3, count, mean_diameter * 1e3,
              need * 1e-9, bytes_per_grain(),
              too_big ? fmt::format(", more than the {:.3g} GB this machine has available", available * 1e-9) : "",
              too_many ? fmt::format(", and more grains than one run can index ({})",
                                     std::numeric_limits<Index>::max())
                       : "",
              side * 1e3, side * 1e3);
}

void check_specimen_fits(const LabSpec& spec) {
  // Volumes only: the meshes' own (collision shapes are not needed here).
  const GrainSet set = make_grain_set(spec.grains, spec.seed);
  double mean_volume = 0;
  for (const TriMesh& mesh : set.meshes) mean_volume += mass_properties(mesh).volume / set.meshes.size();
  const bool known = !spec.targets_own_indices() || spec.own_indices_known();
  const double e = known ? spec.target_void_ratio() : std::min(spec.specimen.e_min, 0.5);
  refuse_impossible_specimen(specimen_grain_count(spec.box, e, mean_volume), available_memory_bytes(), spec.box,
                             std::cbrt(6 * mean_volume / std::numbers::pi),
                             "the specimen (box.length x box.width x box.height)");
}

}  // namespace grainlab
