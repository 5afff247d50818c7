// What the direct shear test measures and records (definitions in
// direct_shear.h): the wall forces and displacements, the sample rows, the
// summary, the band geometry, and the protocol's own bytes.
#include "lab/direct_shear.h"

#include "core/error.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace grainlab {

const std::vector<std::string>& shear_series_columns() {
  static const std::vector<std::string> columns = {
      "time_s",          "shear_strain",      "horizontal_displacement_m", "vertical_displacement_m",
      "shear_force_N",   "normal_force_N",    "normal_stress_Pa",          "stress_ratio",
      "friction_angle_deg", "void_ratio",     "coordination_number",       "kinetic_energy_J",
      "unbalanced_force_ratio", "inertial_number"};
  return columns;
}

double DirectShearTest::shear_strain() const {
  if (phase() < ShearPhase::Shear) return 0;
  return (world().state.walls[UpperXm].x.x() - p_.upper_x_at_shear) / spec_.box.length;
}

double DirectShearTest::shear_force() const {
  double fx = 0;
  for (int r = UpperXm; r <= Cap; ++r) fx += world().state.walls[r].force.x();
  return -fx;
}

double DirectShearTest::cap_displacement() const {
  if (phase() < ShearPhase::Shear) return 0;
  return world().state.walls[Cap].x.z() - p_.cap_z_at_shear;
}

double DirectShearTest::inertial_number() const {
  const double sigma = std::max(normal_stress(), 1e-9);
  const double rho = spec_.material.grain.density * world().model.density_scale;
  return shear_speed_ / spec_.box.height * mean_diameter() * std::sqrt(rho / sigma);
}

void DirectShearTest::record_sample() {
  const double F = shear_force(), N = normal_force();
  const double ratio = N > 0 ? F / N : 0;
  std::vector<double> row = {world().state.time, shear_strain(), shear_strain() * spec_.box.length,
                             cap_displacement(), F, N, normal_stress(), ratio,
                             std::atan(ratio) * 180 / std::numbers::pi, void_ratio(), coordination_number(),
                             world().kinetic_energy(), unbalanced_force_ratio(world()), inertial_number()};
  observe(row);
  p_.rows.push_back(std::move(row));
  while (p_.next_sample_strain <= shear_strain() + 1e-12) p_.next_sample_strain += spec_.output.strain_interval;
}

std::vector<SummaryValue> DirectShearTest::summary() const {
  const ShearSummary s = shear_summary();
  std::vector<SummaryValue> v = {{"", "shear_speed_m_per_s", shear_speed_}};
  for (const SummaryValue& x : prep_->summary()) v.push_back(x);
  const std::vector<SummaryValue> peaks = {{"peaks", "friction_angle_deg", s.peak_friction_angle_deg},
                                           {"peaks", "strain_at_peak_friction", s.strain_at_peak_friction},
                                           {"peaks", "stress_ratio", s.peak_stress_ratio},
                                           {"peaks", "dilation_angle_deg", s.peak_dilation_angle_deg},
                                           {"peaks", "strain_at_peak_dilation", s.strain_at_peak_dilation},
                                           {"final", "friction_angle_deg", s.final_friction_angle_deg},
                                           {"final", "dilation_angle_deg", s.final_dilation_angle_deg},
                                           {"final", "void_ratio", s.final_void_ratio}};
  v.insert(v.end(), peaks.begin(), peaks.end());
  for (const SummaryValue& x : prep_->shape_summary()) v.push_back(x);
  return v;
}

std::string DirectShearTest::status_line() const {
  return fmt::format("strain {:.4f}  stress ratio {:.3f}  sigma {:.1f} kPa  e {:.3f}", shear_strain(),
                     normal_force() > 0 ? shear_force() / normal_force() : 0.0, normal_stress() * 1e-3,
                     void_ratio());
}

std::string DirectShearTest::phase_note() const { return prep_->phase_note(); }

std::string DirectShearTest::result_line() const {
  const ShearSummary s = shear_summary();
  return fmt::format("peak friction angle {:.1f} deg (stress ratio {:.3f}) at strain {:.3f}; peak dilation "
                     "angle {:.1f} deg",
                     s.peak_friction_angle_deg, s.peak_stress_ratio, s.strain_at_peak_friction,
                     s.peak_dilation_angle_deg);
}

std::optional<BandGeometry> DirectShearTest::band_geometry() const {
  BandGeometry b;
  b.z_min = 0;  // the floor
  b.z_max = world().state.walls[Cap].x.z() - cap_displacement();  // the cap at the start of shear (before: now)
  b.layer = mean_diameter();
  b.direction = Vec3::UnitX();
  b.strain = shear_strain();
  b.length = spec_.box.length;
  return b;
}

std::vector<std::uint8_t> DirectShearTest::save() const {
  ByteWriter b;
  prep_->save(b);
  b.i32(static_cast<std::int32_t>(p_.phase));
  b.f64(p_.cap_z_at_shear), b.f64(p_.upper_x_at_shear), b.f64(p_.next_sample_strain);
  b.i64(p_.shear_start_step), b.i64(p_.done_step);
  b.u64(p_.rows.size());
  for (const auto& r : p_.rows) b.f64s(r);
  save_bodies(b, p_.reference);
  return std::move(b.bytes);
}

void DirectShearTest::load(std::span<const std::uint8_t> bytes) {
  ByteReader r(bytes, "the direct shear protocol state", " Start the run again without --resume.");
  prep_->load(r);
  const std::int32_t shear_phase = r.i32();
  if (shear_phase != static_cast<int>(ShearPhase::Shear) && shear_phase != static_cast<int>(ShearPhase::Done))
    r.corrupted("an unknown phase");
  p_.phase = static_cast<ShearPhase>(shear_phase);
  p_.cap_z_at_shear = r.f64(), p_.upper_x_at_shear = r.f64(), p_.next_sample_strain = r.f64();
  p_.shear_start_step = r.i64(), p_.done_step = r.i64();
  p_.rows.resize(r.count(8));
  for (auto& row : p_.rows) row = r.f64s();
  p_.reference = load_bodies(r);
  r.expect_end();
  prep_->hold_cap(prep_->prepared() && p_.phase == ShearPhase::Shear);  // derived, not stored
}

}  // namespace grainlab
