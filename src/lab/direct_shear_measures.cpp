// What the direct shear test measures and records (definitions in
// direct_shear.h): the wall forces and displacements, the sample rows, the
// summary, the band geometry, and the protocol's own bytes.
#include "lab/direct_shear.h"

#include "core/error.h"
#include "lab/packing_density.h"

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
  if (p_.phase < ShearPhase::Shear) return 0;
  return (world_.state.walls[UpperXm].x.x() - p_.upper_x_at_shear) / spec_.box.length;
}

double DirectShearTest::shear_force() const {
  double fx = 0;
  for (int r = UpperXm; r <= Cap; ++r) fx += world_.state.walls[r].force.x();
  return -fx;
}

double DirectShearTest::cap_displacement() const {
  if (p_.phase < ShearPhase::Shear) return 0;
  return world_.state.walls[Cap].x.z() - p_.cap_z_at_shear;
}

double DirectShearTest::void_ratio() const {
  const double v = box_area() * world_.state.walls[Cap].x.z();
  return (v - solid_volume()) / solid_volume();
}

double DirectShearTest::bulk_void_ratio() const {
  const Region r = bulk_region(spec_.box.length, spec_.box.width, world_.state.walls[Cap].x.z(), mean_diameter());
  return void_ratio_in_region(world_.model, world_.state, r.lo, r.hi);
}

double DirectShearTest::achieved_void_ratio() const {
  if (p_.phase < ShearPhase::Shear) return p_.compacted_void_ratio;
  return (box_area() * p_.cap_z_at_shear - solid_volume()) / solid_volume();
}

double DirectShearTest::achieved_own_relative_density() const {
  const auto& s = spec_.specimen;
  if (!spec_.own_indices_known()) return std::numeric_limits<double>::quiet_NaN();
  return (s.own_e_max - p_.compacted_bulk_void_ratio) / (s.own_e_max - s.own_e_min);
}

double DirectShearTest::achieved_lab_relative_density() const {
  const auto& s = spec_.specimen;
  return (s.e_max - achieved_void_ratio()) / (s.e_max - s.e_min);
}

double DirectShearTest::achieved_relative_density() const {
  // A scan's specimen targets no density and may not know its own indices: Dr on the lab's then.
  const bool own = spec_.targets_own_indices() && spec_.own_indices_known();
  return own ? achieved_own_relative_density() : achieved_lab_relative_density();
}

double DirectShearTest::coordination_number() const {
  const std::size_t contacts = touching_pair_count(world_.state.contacts);
  return 2.0 * contacts / std::max<std::size_t>(1, world_.model.bodies.size());
}

double DirectShearTest::inertial_number() const {
  const double sigma = std::max(normal_stress(), 1e-9);
  const double rho = spec_.material.grain.density * world_.model.density_scale;
  return shear_speed_ / spec_.box.height * mean_diameter() * std::sqrt(rho / sigma);
}

std::vector<std::string> DirectShearTest::series_columns() const {
  std::vector<std::string> c = shear_series_columns();
  c.insert(c.end(), observer_columns_.begin(), observer_columns_.end());
  return c;
}

void DirectShearTest::set_sample_observer(std::vector<std::string> columns, SampleObserver observer) {
  observer_columns_ = std::move(columns);
  observer_ = std::move(observer);
}

void DirectShearTest::record_sample() {
  const double F = shear_force(), N = normal_force();
  const double ratio = N > 0 ? F / N : 0;
  std::vector<double> row = {world_.state.time, shear_strain(), shear_strain() * spec_.box.length,
                             cap_displacement(), F, N, normal_stress(), ratio,
                             std::atan(ratio) * 180 / std::numbers::pi, void_ratio(), coordination_number(),
                             world_.kinetic_energy(), unbalanced_force_ratio(world_), inertial_number()};
  if (observer_) {
    const std::vector<double> extra = observer_(*this);
    if (extra.size() != observer_columns_.size())
      throw RunError(fmt::format("sample observer gave {} values for {} columns", extra.size(),
                                 observer_columns_.size()));
    row.insert(row.end(), extra.begin(), extra.end());
  }
  p_.rows.push_back(std::move(row));
  while (p_.next_sample_strain <= shear_strain() + 1e-12) p_.next_sample_strain += spec_.output.strain_interval;
}

std::vector<SummaryValue> DirectShearTest::summary() const {
  const ShearSummary s = shear_summary();
  std::vector<SummaryValue> v = {{"", "shear_speed_m_per_s", shear_speed_},
          {"", "mean_equivalent_diameter_m", mean_diameter()},
          {"preparation", "void_ratio", achieved_void_ratio()},
          {"preparation", "compacted_void_ratio", p_.compacted_void_ratio},
          {"preparation", "relative_density", achieved_relative_density()},
          {"preparation", "bulk_void_ratio", achieved_bulk_void_ratio()},
          {"preparation", "relative_density_lab", achieved_lab_relative_density()},
          {"preparation", "deposition_friction", spec_.specimen.deposition_friction},
          {"preparation", "target_void_ratio", spec_.target_void_ratio()},
          {"peaks", "friction_angle_deg", s.peak_friction_angle_deg},
          {"peaks", "strain_at_peak_friction", s.strain_at_peak_friction},
          {"peaks", "stress_ratio", s.peak_stress_ratio},
          {"peaks", "dilation_angle_deg", s.peak_dilation_angle_deg},
          {"peaks", "strain_at_peak_dilation", s.strain_at_peak_dilation},
          {"final", "friction_angle_deg", s.final_friction_angle_deg},
          {"final", "dilation_angle_deg", s.final_dilation_angle_deg},
          {"final", "void_ratio", s.final_void_ratio}};
  const GrainRepresentation& r = specimen_.representation;
  v.push_back({"grain_shapes", "concave_shapes", static_cast<double>(r.concave_shapes)});
  if (r.concave_shapes > 0) {
    v.push_back({"grain_shapes", "pieces_per_concave_shape", static_cast<double>(r.pieces) / r.concave_shapes});
    v.push_back({"grain_shapes", "hull_excess_volume_fraction", r.hull_excess});
    v.push_back({"grain_shapes", "pieces_excess_volume_fraction", r.pieces_excess});
  }
  if (specimen_.scan.grains > 0) {
    v.push_back({"scan", "grains", static_cast<double>(specimen_.scan.grains)});
    v.push_back({"scan", "border_grains_dropped", static_cast<double>(specimen_.scan.border_dropped)});
    v.push_back({"scan", "position_spread", specimen_.scan.spread});
    v.push_back({"scan", "void_ratio", specimen_.scan.void_ratio});
  }
  if (spec_.own_indices_known()) {
    v.push_back({"preparation", "relative_density_own", achieved_own_relative_density()});
    v.push_back({"preparation", "own_e_min", spec_.specimen.own_e_min});
    v.push_back({"preparation", "own_e_max", spec_.specimen.own_e_max});
  }
  return v;
}

std::string DirectShearTest::status_line() const {
  return fmt::format("strain {:.4f}  stress ratio {:.3f}  sigma {:.1f} kPa  e {:.3f}", shear_strain(),
                     normal_force() > 0 ? shear_force() / normal_force() : 0.0, normal_stress() * 1e-3,
                     void_ratio());
}

std::string DirectShearTest::phase_note() const {
  if (p_.phase != ShearPhase::Consolidate) return "";
  if (spec_.targets_own_indices() && spec_.own_indices_known())
    return fmt::format("prepared: bulk void ratio {:.3f} (target {:.3f}), Dr {:.0f} % on the grains' own indices "
                       "(whole specimen e {:.3f})",
                       achieved_bulk_void_ratio(), spec_.target_void_ratio(), 100 * achieved_relative_density(),
                       achieved_void_ratio());
  return fmt::format("prepared: void ratio {:.3f} (target {:.3f}), Dr {:.0f} %", achieved_void_ratio(),
                     spec_.target_void_ratio(), 100 * achieved_relative_density());
}

std::string DirectShearTest::result_line() const {
  const ShearSummary s = shear_summary();
  return fmt::format("peak friction angle {:.1f} deg (stress ratio {:.3f}) at strain {:.3f}; peak dilation "
                     "angle {:.1f} deg",
                     s.peak_friction_angle_deg, s.peak_stress_ratio, s.strain_at_peak_friction,
                     s.peak_dilation_angle_deg);
}

BandGeometry DirectShearTest::band_geometry() const {
  BandGeometry b;
  b.z_min = 0;  // the floor
  b.z_max = world_.state.walls[Cap].x.z() - cap_displacement();  // the cap at the start of shear (before: now)
  b.layer = mean_diameter();
  b.direction = Vec3::UnitX();
  b.strain = shear_strain();
  b.length = spec_.box.length;
  return b;
}

std::vector<std::uint8_t> DirectShearTest::save() const {
  ByteWriter b;
  b.i32(static_cast<std::int32_t>(p_.phase));
  p_.rest.save(b);
  servo_.save(b);
  b.f64(p_.compacted_void_ratio), b.f64(p_.compacted_bulk_void_ratio), b.f64(p_.cap_z_at_shear), b.f64(p_.upper_x_at_shear);
  b.f64(p_.next_sample_strain);
  for (auto s : p_.phase_start_step) b.i64(s);
  b.u64(p_.rows.size());
  for (const auto& r : p_.rows) b.f64s(r);
  b.u64(p_.reference.size());
  for (const BodyState& body : p_.reference) b.vec(body.x), b.vec(body.v), b.vec(body.w), b.quat(body.q);
  return std::move(b.bytes);
}

void DirectShearTest::load(std::span<const std::uint8_t> bytes) {
  ByteReader r(bytes, "the direct shear protocol state", " Start the run again without --resume.");
  const std::int32_t phase = r.i32();
  if (phase < 0 || phase > static_cast<int>(ShearPhase::Done)) r.corrupted("an unknown phase");
  p_.phase = static_cast<ShearPhase>(phase);
  p_.rest.load(r);
  servo_.load(r);
  p_.compacted_void_ratio = r.f64(), p_.compacted_bulk_void_ratio = r.f64(), p_.cap_z_at_shear = r.f64(), p_.upper_x_at_shear = r.f64();
  p_.next_sample_strain = r.f64();
  for (auto& s : p_.phase_start_step) s = r.i64();
  p_.rows.resize(r.count(8));
  for (auto& row : p_.rows) row = r.f64s();
  p_.reference.resize(r.count(13 * 8));
  for (BodyState& body : p_.reference) body.x = r.vec(), body.v = r.vec(), body.w = r.vec(), body.q = r.quat();
  r.expect_end();
  apply_phase_overrides();  // the phase's settings are derived, not stored
}

}  // namespace grainlab
