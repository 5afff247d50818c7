// The forces phase of World::step: the contact law over every touching
// contact (four at a time, in parallel, each writing only its own contact),
// then the serial sums, in contact order, of gravity and the contact forces
// and torques per body, and of the grains' forces per wall. Kept in one
// translation unit with the laws it instantiates (dynamics/laws/registry.h),
// so that the hot formulas inline into the loop as they always did (GCC
// contracts a*b + c into FMA where it inlines: moving them would move bits).
#pragma once

#include "core/types.h"
#include "dynamics/material.h"
#include "dynamics/model.h"
#include "dynamics/state.h"

#include <cstddef>
#include <functional>
#include <vector>

namespace grainlab {

// Grain-grain contacts made during the forces phase, a few at a time (a
// world of spheres stepped serially, CollisionDriver's compact pass):
// more(k) appends about k contacts (a few more or fewer) to *list, in
// contact order, and returns how many (0 when done). Each batch is pushed by
// the law and summed before the next is made: the same arithmetic in the
// same order as over a whole list (a contact's lanes do not mix with its
// neighbours').
struct GrainContactSource {
  std::vector<Contact>* list = nullptr;
  std::function<std::size_t(std::size_t)> more;
};

// What the forces phase reads besides the contacts: the World's pair table
// (materials x materials, the Model's coefficients with the phase's
// overrides), the gravity in effect, and the step's threads.
struct ForceStep {
  const Model& model;
  State& state;
  const std::vector<PairCoefficients>& pair_table;
  Vec3 gravity;
  int threads = 1;
  std::ptrdiff_t serial_below = 0;  // WorldSettings::serial_below
  // Null: the grain contacts are State::contacts, made by the narrowphase;
  // else they come from here (and the loops run serially).
  GrainContactSource* source = nullptr;
};

// Sets every contact's force, normal force, torque and carried spring, every
// wall's force, and each body's resultant force and torque (gravity
// included), for the model's contact law.
void contact_forces(const ForceStep& s, double dt, std::vector<Vec3>& force, std::vector<Vec3>& torque);

}  // namespace grainlab
