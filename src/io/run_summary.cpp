// run.json micromechanics entries (see run_summary.h).
#include "io/run_summary.h"

#include "analysis/stress.h"
#include "geometry/shape_metrics.h"

#include <cmath>
#include <exception>
#include <vector>

namespace grainlab {

std::optional<double> mean_grain_roundness(const Model& model) {
  if (model.bodies.empty()) return std::nullopt;
  std::vector<std::size_t> uses(model.shapes.size(), 0);
  for (const BodyModel& b : model.bodies) ++uses[b.shape];
  double sum = 0;
  for (std::size_t s = 0; s < model.shapes.size(); ++s) {
    if (uses[s] == 0) continue;
    const Shape& shape = model.shapes[s];
    double r = 1;  // a sphere is perfectly round
    if (shape.kind == Shape::Kind::Polytope) {
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

void add_micromechanics_summary(nlohmann::json& j, const LabTest& test) {
  if (const auto r = mean_grain_roundness(test.world().model)) j["mean_roundness"] = *r;

  // Peak Psi over the series (NaN rows, before a contact exists, are skipped).
  const std::vector<std::string> columns = test.series_columns();
  for (std::size_t c = 0; c < columns.size(); ++c) {
    if (columns[c] != "fabric_psi") continue;
    double peak = -1;
    for (const auto& row : test.series())
      if (std::isfinite(row[c]) && row[c] > peak) peak = row[c];
    if (peak >= 0) j["peaks"]["fabric_psi"] = peak;
  }

  const World& w = test.world();
  const double volume = test.specimen_volume();
  const analysis::StressTensor s = analysis::love_weber_stress(w.state, volume);
  nlohmann::json sigma = nlohmann::json::array();
  for (int i = 0; i < 3; ++i) sigma.push_back({s.sigma(i, 0), s.sigma(i, 1), s.sigma(i, 2)});
  nlohmann::json& f = j["final"];
  f["cap_normal_stress_Pa"] = test.boundary_stress();
  f["love_weber_stress_Pa"] = std::move(sigma);
  f["love_weber_mean_Pa"] = s.mean;
  f["love_weber_deviatoric_Pa"] = s.deviatoric;
  f["love_weber_asymmetry"] = s.asymmetry;
  f["specimen_volume_m3"] = volume;
}

}  // namespace grainlab
