// Rotation angle of grains (paper Eq. 21) between a reference and a current State.
//
// A unit quaternion q = (w, v) = (cos(theta/2), u sin(theta/2)) rotates by
// theta about the unit axis u (Eq. 20). The rotation a grain made since the
// reference is the relative rotation q_rel = q_now * q_ref^-1 (world frame;
// q_ref^-1 * q_now, the same rotation seen in the reference body frame, has the
// same angle because the two are conjugate). Eq. 21 reads theta = 2 acos(q0),
// which has two flaws in floating point:
//  * q and -q are the same rotation (the double cover), yet acos(q0) and
//    acos(-q0) differ: with q0 < 0 Eq. 21 gives 2 pi - theta. The angle of the
//    rotation is 2 acos(|q0|), in [0, pi].
//  * near identity acos is ill-conditioned (d acos/dx -> infinity at 1): a
//    rounding error of 1e-16 in q0 gives an angle error of ~3e-8 rad, and an
//    angle below ~1e-8 rad is lost entirely.
// So grainlab uses theta = 2 atan2(|v|, |w|), exact in both limits and
// insensitive to the quaternion's norm (atan2 takes a ratio). Angles in rad.
#pragma once

#include "analysis/grain_mask.h"
#include "core/types.h"
#include "dynamics/state.h"

#include <vector>

namespace grainlab::analysis {

// Angle of the rotation q (rad, in [0, pi]); q need not be normalised.
double rotation_angle(const Quat& q);

// Angle of the rotation that takes orientation q_ref to q_now (rad, in [0, pi]).
double relative_rotation_angle(const Quat& q_now, const Quat& q_ref);

// Per grain: the angle each body turned through between `ref` and `now` (rad).
// The two States must hold the same bodies.
std::vector<double> rotation_angles(const State& now, const State& ref);

// Mean rotation angle (rad) over all grains, or over the grains in `mask` when
// given; NaN when the set is empty.
double mean_rotation_angle(const State& now, const State& ref, const GrainMask* mask = nullptr);

}  // namespace grainlab::analysis
