// Critical time step (derivation in time_step.h).
#include "dynamics/time_step.h"

#include "dynamics/contact_law.h"

#include <cmath>
#include <limits>

namespace grainlab {

TimeStepEstimate critical_time_step(const Model& model, double fraction) {
  TimeStepEstimate best;
  best.critical = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < model.bodies.size(); ++i) {
    const BodyModel& b = model.bodies[i];
    const double r = b.bounding_radius;
    const double m_c = 1.0 / (b.inv_mass + r * r * b.inv_inertia.maxCoeff());
    const double delta = fraction * b.radius;
    for (std::size_t other = 0; other < model.materials.size(); ++other) {
      const PairCoefficients& p = model.pair(b.material, static_cast<Index>(other));
      // Grain-grain with an equal grain (R* = R/2, m* = m_c/2) and grain-wall (R* = R, m* = m_c).
      for (const auto& [r_eff, m_eff] : {std::pair{0.5 * b.radius, 0.5 * m_c}, std::pair{b.radius, m_c}}) {
        const bool wall = r_eff == b.radius;
        // A contact that cannot happen sets no limit.
        if (wall ? model.walls.empty() : model.bodies.size() < 2) continue;
        const LawCoefficients k = model.law->at(p, delta, r_eff, m_eff);
        const double stiff = std::max(model.law->stiffness(k), k.k_t);
        const double dt = 2.0 * std::sqrt(m_eff / stiff);
        if (dt < best.critical) best = {dt, static_cast<Index>(i), stiff};
      }
    }
  }
  return best;
}

}  // namespace grainlab
