// The end-of-run micromechanics summary (contents in micromechanics.h).
#include "analysis/micromechanics.h"

#include "geometry/shape_metrics.h"

#include <cmath>
#include <exception>
#include <vector>

namespace grainlab::analysis {

std::optional<double> mean_grain_roundness(const Model& model) {
  if (model.bodies.empty()) return std::nullopt;
  std::vector<std::size_t> uses(model.shapes.size(), 0);
  for (const BodyModel& b : model.bodies) ++uses[b.shape];
  double sum = 0;
  for (std::size_t s = 0; s < model.shapes.size(); ++s) {
    if (uses[s] == 0) continue;
    const Shape& shape = model.shapes[s];
    double r = 1;  // a sphere is perfectly round
    if (shape.kind != Shape::Kind::Sphere) {  // the mesh: exact for concave grains too
      try {
        r = shape_metrics(shape.mesh).roundness;  // scale-free: the library shape stands for its grains
      } catch (const std::exception&) {
        return std::nullopt;
      }
    }
    if (!std::isfinite(r)) return std::nullopt;
    sum += r * static_cast<double>(uses[s]);
  }
  return sum / static_cast<double>(model.bodies.size());
}

MicromechanicsSummary micromechanics_summary(const Model& model, const State& state, double specimen_volume,
                                             std::span<const double> fabric_psi,
                                             std::span<const double> fabric_psi_band) {
  MicromechanicsSummary m;
  m.mean_roundness = mean_grain_roundness(model);
  m.peak_fabric_psi = series_peak(fabric_psi);
  m.peak_fabric_psi_band = series_peak(fabric_psi_band);
  m.specimen_volume = specimen_volume;
  m.love_weber = love_weber_stress(state, m.specimen_volume);
  m.forces = force_stats(state);
  return m;
}

}  // namespace grainlab::analysis
