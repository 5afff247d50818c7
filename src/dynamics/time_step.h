// Critical time step of an explicit DEM step.
//
// One contact is a spring of stiffness k between effective masses; the
// semi-implicit Euler step is stable for dt < 2 sqrt(m/k) (the central
// difference limit 2/omega). The normal stiffness is the law's tangent
// k = d f_n / d delta at the expected overlap delta_ref (the law's stiffness()).
// Rotation makes a contact feel lighter: a force at lever arm r on a body of
// mass m and smallest principal moment I moves the contact point as a mass
// m_c = 1 / (1/m + r^2/I); r is the bounding radius (the worst case). The
// tangential spring is checked the same way. The smallest grain-grain
// (m* = m_c/2) and grain-wall (m* = m_c) value over all bodies is returned;
// infinity if no contact can happen (one grain and no walls).
#pragma once

#include "dynamics/model.h"

namespace grainlab {

struct TimeStepEstimate {
  double critical = 0;        // s
  Index limiting_body = -1;   // the body that sets it
  double stiffness = 0;       // N/m of the limiting contact
};

TimeStepEstimate critical_time_step(const Model& model, double expected_overlap_fraction);

}  // namespace grainlab
