// Critical time step of an explicit DEM step.
//
// One contact is a damped spring between effective masses:
//     m x'' = -k x - c x',  omega = sqrt(k/m),  zeta = c / (2 sqrt(k m)).
// The step (World::step: forces at x_n, v_n; then v_{n+1}, then x_{n+1} with
// v_{n+1}: semi-implicit Euler) maps (x, v) by
//     [[1 - w^2 h^2, h (1 - 2 zeta w h)], [-w^2 h, 1 - 2 zeta w h]]   (w h = omega dt),
// with trace 2 - w^2h^2 - 2 zeta w h and determinant 1 - 2 zeta w h. Both
// eigenvalues stay in the unit circle (Jury: |det| <= 1, |tr| <= 1 + det) iff
//     omega dt <= 2 (sqrt(1 + zeta^2) - zeta),
// which is the undamped 2/omega at zeta = 0 and shrinks as damping grows
// (0.70 of it at zeta = 0.37). The damping is explicit (it uses v_n), so a
// heavily damped contact can flip its velocity every step and pump energy in.
//
// The normal stiffness is the law's tangent k = d f_n / d delta at the
// expected overlap delta_ref (the law's stiffness()); the tangential one is
// the law's K_t. Rotation makes a contact feel lighter: a force at lever arm
// r on a body of mass m and smallest principal moment I moves the contact
// point as a mass m_c = 1 / (1/m + r^2/I); r is the bounding radius (the
// worst case). The damping coefficients are the ones the force loop uses
// (computed with the translational m* = m/2 or m), but they act on that
// lighter point: for a sphere m_c = 2m/7, so the tangential damping ratio of
// the contact point is sqrt(7/2) times the nominal one. The smallest
// grain-grain (oscillator mass m_c/2, R* = R/2) and grain-wall (m_c, R) value
// over all bodies, both directions, is returned; infinity if no contact can
// happen (one grain and no walls).
//
// The damping enters for isotropic bodies (spheres), where m_c = 2m/7 is
// exact, and for concave grains (compound shapes). For faceted grains m_c is
// a worst case (the bounding radius and the smallest moment), and with the
// damping computed from the whole body's m* the worst-case zeta is 0.76 for
// the sub-angular preset (1.01 angular), which halves their step (measured
// with the presets at restitution 0.5). Convex faceted grains keep the
// undamped bound 2 sqrt(m_c/k): every preset deposits, compacts and shears
// with it, at deposition friction up to 1. Concave grains did not: a pair of
// them touches at several places at once (one result per piece pair), so a
// grain in a loose deposit at friction 1 feels several parallel springs and
// dampers, and at 0.4 of the undamped bound spherical-harmonic grains spun
// up in a period-two oscillation (angular velocity flipping every step, a
// grain's contacts pulling on every other step) until one went non-finite
// (measured 2026-12-07: no fault without damping, none without friction,
// none at the damped bound; docs/grains.md).
//
// Why the damping term matters (measured): glass beads (e = 0.5) deposited
// at friction 0.6 or 1.0 with 0.4 of the undamped step never came to rest:
// the uniform spin of all grains (every contact slides at 2 r |w x n|) is
// damped by several sticking contacts at once, overshot every step, and
// spun beads up to 3e3 rad/s. With the damping-aware step they settle.
#pragma once

#include "dynamics/model.h"

namespace grainlab {

struct TimeStepEstimate {
  double critical = 0;        // s
  Index limiting_body = -1;   // the body that sets it
  double stiffness = 0;       // N/m of the limiting contact
  double damping_ratio = 0;   // zeta the limit was computed with (0 for faceted grains, see above)
};

// The stable limit 2 (sqrt(1 + zeta^2) - zeta) / omega of one damped spring
// (derivation above); infinity for k <= 0.
double damped_critical_step(double stiffness, double damping, double mass);

TimeStepEstimate critical_time_step(const Model& model, double expected_overlap_fraction);

}  // namespace grainlab
