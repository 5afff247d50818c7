// The direct shear protocol (see direct_shear.h for the box, the phases and
// the measured quantities).
#include "lab/direct_shear.h"

#include "core/error.h"

#include <cmath>

namespace grainlab {

const char* shear_phase_name(ShearPhase p) {
  switch (p) {
    case ShearPhase::Shear: return "shear";
    case ShearPhase::Done: return "done";
    default: return preparation_phase_name(static_cast<PreparationPhase>(static_cast<int>(p)));
  }
}

DirectShearTest::DirectShearTest(const LabSpec& spec)
    : DirectShearTest(spec, std::make_unique<SpecimenPreparation>(spec)) {}

DirectShearTest::DirectShearTest(const LabSpec& spec, std::unique_ptr<SpecimenPreparation> preparation)
    : PreparedTest(spec, std::move(preparation)) {
  // Shear speed for the requested inertial number I = (v / H) d sqrt(rho S / sigma).
  const double rho = spec.material.grain.density * world().model.density_scale;
  shear_speed_ = spec.settings<ShearSpec>().speed > 0 ? spec.settings<ShearSpec>().speed
                                      : spec.numerics.inertial_number * spec.box.height /
                                            (mean_diameter() * std::sqrt(rho / spec.consolidation.normal_stress));
}

std::int64_t DirectShearTest::phase_step(ShearPhase p) const {
  if (p == ShearPhase::Shear) return p_.shear_start_step;
  if (p == ShearPhase::Done) return p_.done_step;
  return prep_->phase_step(static_cast<PreparationPhase>(static_cast<int>(p)));
}

void DirectShearTest::start_shear() {
  World& w = world();
  p_.phase = ShearPhase::Shear;
  p_.shear_start_step = w.state.step;
  prep_->hold_cap(true);  // the cap's servo holds the normal stress while the box shears
  open_shear_box_gap(w, spec_.box);
  p_.cap_z_at_shear = w.state.walls[Cap].x.z();
  p_.upper_x_at_shear = w.state.walls[UpperXm].x.x();
  p_.next_sample_strain = 0;
  p_.reference = w.state.bodies;
  for (int r = UpperXm; r <= UpperYp; ++r) w.state.walls[r].v = Vec3(shear_speed_, 0, 0);
  w.state.walls[Cap].v.x() = shear_speed_;
  record_sample();
}

void DirectShearTest::finish() {
  p_.phase = ShearPhase::Done;
  p_.done_step = world().state.step;
  prep_->hold_cap(false);
  for (int r = UpperXm; r <= Cap; ++r) world().state.walls[r].v.setZero();
}

bool DirectShearTest::advance(int max_steps) {
  if (!prep_->prepared()) {
    if (!prep_->advance(max_steps)) start_shear();
    return true;  // a preparation phase ended, or the steps are done
  }
  World& w = world();
  for (int i = 0; i < max_steps && p_.phase == ShearPhase::Shear; ++i) {
    w.step(time_step());
    if (w.state.step % kCheckEvery == 0) prep_->check_grains_inside(phase_name(), true);
    const bool sampled = shear_strain() + 1e-12 >= p_.next_sample_strain;
    if (sampled) record_sample();
    if (shear_strain() >= spec_.settings<ShearSpec>().final_strain) {
      finish();
      return false;
    }
    if (sampled) return true;
  }
  return p_.phase != ShearPhase::Done;
}

}  // namespace grainlab
