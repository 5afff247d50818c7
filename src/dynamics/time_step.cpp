// Critical time step (derivation in time_step.h).
#include "dynamics/time_step.h"

#include "dynamics/contact_law.h"

#include <cmath>
#include <limits>

namespace grainlab {

double damped_critical_step(double stiffness, double damping, double mass) {
  if (!(stiffness > 0)) return std::numeric_limits<double>::infinity();
  const double zeta = damping / (2.0 * std::sqrt(stiffness * mass));
  return 2.0 * std::sqrt(mass / stiffness) * (std::sqrt(1.0 + zeta * zeta) - zeta);
}

TimeStepEstimate critical_time_step(const Model& model, double fraction) {
  TimeStepEstimate best;
  best.critical = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < model.bodies.size(); ++i) {
    const BodyModel& b = model.bodies[i];
    const double r = b.bounding_radius;
    const double m_c = 1.0 / (b.inv_mass + r * r * b.inv_inertia.maxCoeff());
    const double delta = fraction * b.radius;
    // The damping enters for spheres (where the point mass is exact) and for
    // concave grains (whose pairs touch at several places at once); convex
    // faceted grains keep the undamped bound (time_step.h).
    const Shape& shape = model.shapes[b.shape];
    const bool damped = shape.isotropic || shape.kind == ShapeKind::Compound;
    for (std::size_t other = 0; other < model.materials.size(); ++other) {
      const PairCoefficients& p = model.pair(b.material, static_cast<Index>(other));
      // Grain-grain with an equal grain (R* = R/2, m* = m/2, point mass m_c/2)
      // and grain-wall (R* = R, m* = m, point mass m_c).
      for (const double share : {0.5, 1.0}) {
        const bool wall = share == 1.0;
        // A contact that cannot happen sets no limit.
        if (wall ? model.walls.empty() : model.bodies.size() < 2) continue;
        const double m_point = share * m_c;
        const LawCoefficients k = model.law->at(p, delta, share * b.radius, share * b.mass);
        const double k_n = model.law->stiffness(k);
        for (const auto& [stiff, damp] : {std::pair{k_n, k.c_n}, std::pair{k.k_t, k.c_t}}) {
          const double used = damped ? damp : 0.0;
          const double dt = damped_critical_step(stiff, used, m_point);
          if (dt < best.critical)
            best = {dt, static_cast<Index>(i), stiff, used / (2.0 * std::sqrt(stiff * m_point))};
        }
      }
    }
  }
  return best;
}

}  // namespace grainlab
