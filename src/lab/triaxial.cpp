// The drained triaxial protocol, its measurements and its summary
// (definitions in triaxial.h).
#include "lab/triaxial.h"

#include "core/error.h"
#include "core/line_fit.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace grainlab {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr std::int64_t kMaxIsotropicSteps = 400000;  // as the direct shear's phases

using C = TriaxialColumn;

// The sides: their two slabs, axis and inward direction.
struct Side {
  Index lower, upper;
  int axis;
  double inward;
};
constexpr Side kSides[4] = {{LowerXm, UpperXm, 0, 1.0},
                            {LowerXp, UpperXp, 0, -1.0},
                            {LowerYm, UpperYm, 1, 1.0},
                            {LowerYp, UpperYp, 1, -1.0}};

double friction_angle_deg(double eta) {  // triaxial compression: sin phi = 3 eta / (6 + eta)
  return std::asin(std::clamp(3 * eta / (6 + eta), -1.0, 1.0)) * 180 / std::numbers::pi;
}

// Vermeer and de Borst's triaxial dilatancy angle for r = d eps_v / d eps_a.
double dilatancy_angle_deg(double r) {
  return std::asin(std::clamp(-r / (2 - r), -1.0, 1.0)) * 180 / std::numbers::pi;
}

}  // namespace

const std::vector<std::string>& triaxial_series_columns() {
  static const std::vector<std::string> columns = {
      "time_s",           "axial_strain",         "volumetric_strain",     "axial_stress_Pa",
      "cell_pressure_Pa", "deviator_stress_Pa",   "mean_stress_Pa",        "stress_ratio",
      "side_stress_error", "void_ratio",          "coordination_number",   "kinetic_energy_J",
      "unbalanced_force_ratio", "inertial_number"};
  return columns;
}

TriaxialSummary summarise_triaxial(const std::vector<std::vector<double>>& rows) {
  TriaxialSummary s;
  if (rows.size() < 2) return s;
  // eta averaged over the samples within 0.5 % of axial strain either side.
  const auto smoothed = [&](std::size_t i, int column) {
    double sum = 0;
    int n = 0;
    for (const auto& r : rows)
      if (std::abs(r[C::AxialStrain] - rows[i][C::AxialStrain]) <= 0.005 + 1e-12) sum += r[column], ++n;
    return sum / n;
  };
  std::size_t peak = 0, q_peak = 0;
  double best = -1e300;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const double eta = smoothed(i, C::Ratio);
    if (eta > best) best = eta, peak = i;
    if (rows[i][C::Deviator] > rows[q_peak][C::Deviator]) q_peak = i;
  }
  s.peak_stress_ratio = best;
  s.strain_at_peak = rows[peak][C::AxialStrain];
  s.peak_friction_angle_deg = friction_angle_deg(s.peak_stress_ratio);
  // Critical state: eta over the last fifth of the axial strain, and the
  // dilatancy there from the least-squares slope of eps_v on eps_a.
  const double last = rows.back()[C::AxialStrain];
  double sum = 0;
  LineFit volume;
  for (const auto& r : rows)
    if (r[C::AxialStrain] >= 0.8 * last) sum += r[C::Ratio], volume.add(r[C::AxialStrain], r[C::VolumetricStrain]);
  s.critical_stress_ratio = sum / volume.n;
  s.critical_friction_angle_deg = friction_angle_deg(s.critical_stress_ratio);
  s.critical_dilatancy_angle_deg = dilatancy_angle_deg(volume.slope());  // NaN stays NaN
  // Peak dilatancy: r = d eps_v / d eps_a over 1 % of axial strain.
  s.peak_dilatancy_angle_deg = kNaN;
  for (std::size_t i = 0, j = 0; i < rows.size(); ++i) {
    j = std::max(j, i);
    while (j < rows.size() && rows[j][C::AxialStrain] < rows[i][C::AxialStrain] + 0.01) ++j;
    if (j == rows.size()) break;
    const double r = (rows[j][C::VolumetricStrain] - rows[i][C::VolumetricStrain]) /
                     (rows[j][C::AxialStrain] - rows[i][C::AxialStrain]);
    const double psi = dilatancy_angle_deg(r);
    if (!(psi <= s.peak_dilatancy_angle_deg)) s.peak_dilatancy_angle_deg = psi;
  }
  // E50: where q first reaches half its peak (raw samples), interpolated.
  const double half = 0.5 * rows[q_peak][C::Deviator];
  s.e50_Pa = kNaN;
  for (std::size_t i = 1; i <= q_peak; ++i)
    if (rows[i][C::Deviator] >= half) {
      const double q0 = rows[i - 1][C::Deviator], q1 = rows[i][C::Deviator];
      const double e0 = rows[i - 1][C::AxialStrain], e1 = rows[i][C::AxialStrain];
      const double eps = e0 + (half - q0) / (q1 - q0) * (e1 - e0);
      if (eps > 0) s.e50_Pa = half / eps;
      break;
    }
  s.final_void_ratio = rows.back()[C::VoidRatio];
  return s;
}

TriaxialTest::TriaxialTest(const LabSpec& spec)
    : TriaxialTest(spec, std::make_unique<SpecimenPreparation>(preparation_spec(spec))) {}

TriaxialTest::TriaxialTest(const LabSpec& spec, std::unique_ptr<SpecimenPreparation> preparation)
    : ClosedBoxTest(spec, std::move(preparation)) {
  const double sigma3 = spec.consolidation.normal_stress;
  const double limit = prep_->servo_speed_limit();  // as the preparation's servo
  cap_servo_ = StressServo(Cap, spec.box.length * spec.box.width, sigma3, limit);
  for (int k = 0; k < 4; ++k)
    side_servos_[k] = StressServo({kSides[k].lower, kSides[k].upper}, 2, kSides[k].axis, kSides[k].inward,
                                  side_area(k), sigma3, limit, kSideAlpha);
  // I = (v / H) d sqrt(rho S / sigma_3), H the target height.
  const double rho = spec.material.grain.density * world().model.density_scale;
  axial_speed_ = spec.numerics.inertial_number * spec.box.height / (prep_->mean_diameter() * std::sqrt(rho / sigma3));
  world().add_controller([this](World& w, double dt_step) {
    if (p_.phase != TriaxialPhase::Isotropic && p_.phase != TriaxialPhase::Shear) return;
    for (int k = 0; k < 4; ++k) {
      side_servos_[k].set_area(side_area(k));
      side_servos_[k].control(w, dt_step);
    }
    if (p_.phase == TriaxialPhase::Isotropic) {
      cap_servo_.set_area(length(0) * length(1));
      cap_servo_.control(w, dt_step);
    }
  });
}

double TriaxialTest::cap_height() const { return world().state.walls[Cap].x.z(); }

double TriaxialTest::length(int axis) const {
  const auto& w = world().state.walls;
  const Index lo = axis == 0 ? LowerXm : LowerYm, hi = axis == 0 ? LowerXp : LowerYp;
  return w[hi].x[axis] - w[lo].x[axis] - kShearBoxSlab;
}

double TriaxialTest::side_area(int side) const { return length(side < 2 ? 1 : 0) * cap_height(); }

double TriaxialTest::axial_stress() const { return world().state.walls[Cap].force.z() / (length(0) * length(1)); }

double TriaxialTest::side_stress(int side) const {
  const Side& s = kSides[side];
  const auto& w = world().state.walls;
  return -s.inward * (w[s.lower].force[s.axis] + w[s.upper].force[s.axis]) / side_area(side);
}

double TriaxialTest::cell_pressure() const {
  return 0.25 * (side_stress(0) + side_stress(1) + side_stress(2) + side_stress(3));
}

double TriaxialTest::axial_strain() const {
  if (p_.phase < TriaxialPhase::Shear) return 0;
  return (p_.height_at_shear - cap_height()) / p_.height_at_shear;
}

double TriaxialTest::volumetric_strain() const {
  if (p_.phase < TriaxialPhase::Shear) return 0;
  return (p_.volume_at_shear - specimen_volume()) / p_.volume_at_shear;
}

double TriaxialTest::void_ratio() const {
  const double vs = prep_->solid_volume();
  return (specimen_volume() - vs) / vs;
}

int TriaxialTest::phase_index() const {
  // deposit 0, compact 1, consolidate 2 (the preparation's), isotropic 3, shear 4, done 5.
  return p_.phase == TriaxialPhase::Prepare ? static_cast<int>(prep_->phase()) : 2 + static_cast<int>(p_.phase);
}

std::string TriaxialTest::phase_name() const {
  switch (p_.phase) {
    case TriaxialPhase::Prepare: return prep_->phase_name();
    case TriaxialPhase::Isotropic: return "isotropic";
    case TriaxialPhase::Shear: return "shear";
    case TriaxialPhase::Done: return "done";
  }
  return "?";
}

void TriaxialTest::enter(TriaxialPhase p) {
  p_.phase = p;
  p_.phase_start_step = world().state.step;
  p_.rest.reset();
  auto& walls = world().state.walls;
  if (p == TriaxialPhase::Shear) {
    p_.shear_start_step = world().state.step;
    p_.height_at_shear = cap_height();
    p_.volume_at_shear = specimen_volume();
    p_.reference = world().state.bodies;
    p_.next_sample_strain = 0;
    walls[Cap].v = Vec3(0, 0, -axial_speed_);
    record_sample();
  }
  if (p == TriaxialPhase::Done)
    for (WallState& w : walls) w.v.setZero();
}

bool TriaxialTest::isotropic_at_rest() {
  const auto& c = spec_.consolidation;
  const double target = c.normal_stress;
  bool stresses = std::abs(axial_stress() / target - 1) <= c.tolerance;
  for (int k = 0; k < 4; ++k) stresses = stresses && std::abs(side_stress(k) / target - 1) <= c.tolerance;
  const bool rest = p_.rest.check(stresses && kinetic_small_against_elastic(world()), world(), c.max_unbalanced);
  const std::int64_t in_phase = world().state.step - p_.phase_start_step;
  if (!rest && in_phase > kMaxIsotropicSteps)
    throw RunError(fmt::format(
        "the isotropic consolidation did not come to rest in {} steps (cap {:.4g} Pa, sides {:.4g}, {:.4g}, {:.4g}, "
        "{:.4g} Pa against {:.4g} Pa; kinetic energy {:.3g} J): try a smaller time step, more damping (lower "
        "restitution) or a larger consolidation.max_unbalanced",
        in_phase, axial_stress(), side_stress(0), side_stress(1), side_stress(2), side_stress(3), target,
        world().kinetic_energy()));
  return rest;
}

void TriaxialTest::check_corners() const {
  // A side may move outwards by less than the slab thickness before a corner opens.
  const double out_x = 0.5 * (length(0) - spec_.box.length), out_y = 0.5 * (length(1) - spec_.box.width);
  if (std::max(out_x, out_y) > 0.9 * kShearBoxSlab)
    throw RunError(fmt::format(
        "triaxial: the specimen widened by {:.3g} mm on a side, nearly the {:.3g} mm the side walls overlap "
        "each other; at this strain the box's corners would open. Stop at a smaller triaxial.final_strain or "
        "use a taller specimen (box.height)",
        1e3 * std::max(out_x, out_y), 1e3 * kShearBoxSlab));
}

bool TriaxialTest::advance(int max_steps) {
  if (p_.phase == TriaxialPhase::Done) return false;
  if (p_.phase == TriaxialPhase::Prepare) {
    if (prepare(max_steps)) enter(TriaxialPhase::Isotropic);
    return true;  // a preparation phase ended, or the steps are done
  }
  World& w = world();
  for (int i = 0; i < max_steps; ++i) {
    w.step(time_step());
    if (p_.phase == TriaxialPhase::Shear) {
      for (int k = 0; k < 4; ++k) p_.side_stress_sum[k] += side_stress(k);
      ++p_.steps_since_sample;
      const bool sampled = axial_strain() + 1e-12 >= p_.next_sample_strain;
      if (sampled) {
        check_corners();
        record_sample();
      }
      if (axial_strain() >= spec_.settings<TriaxialSpec>().final_strain) {
        enter(TriaxialPhase::Done);
        return false;
      }
      if (sampled) return true;
      continue;
    }
    p_.rest.add(w.body_forces());
    if (w.state.step % kCheckEvery != 0 || !isotropic_at_rest()) continue;
    enter(TriaxialPhase::Shear);
    return true;
  }
  return true;
}

void TriaxialTest::record_sample() {
  const World& w = world();
  const double s1 = axial_stress(), s3 = cell_pressure();
  const double q = s1 - s3, p = (s1 + 2 * s3) / 3;
  double side_error = 0;  // of the sides' mean stresses since the last sample (this step's at the first)
  for (int k = 0; k < 4; ++k) {
    const double mean = p_.steps_since_sample > 0 ? p_.side_stress_sum[k] / p_.steps_since_sample : side_stress(k);
    side_error = std::max(side_error, std::abs(mean / spec_.consolidation.normal_stress - 1));
  }
  p_.side_stress_sum = {};
  p_.steps_since_sample = 0;
  const double rho = spec_.material.grain.density * w.model.density_scale;
  const double inertial = axial_speed_ / p_.height_at_shear * prep_->mean_diameter() * std::sqrt(rho / std::max(p, 1e-9));
  std::vector<double> row = {w.state.time,  axial_strain(), volumetric_strain(), s1,
                             s3,            q,              p,                   p > 0 ? q / p : kNaN,
                             side_error,    void_ratio(),   prep_->coordination_number(),
                             w.kinetic_energy(), unbalanced_force_ratio(w), inertial};
  observe(row);
  p_.rows.push_back(std::move(row));
  while (p_.next_sample_strain <= axial_strain() + 1e-12) p_.next_sample_strain += spec_.output.strain_interval;
}

std::vector<SummaryValue> TriaxialTest::summary() const {
  std::vector<SummaryValue> v = prep_->summary();
  v.push_back({"", "axial_speed_m_per_s", axial_speed_});
  const TriaxialSummary t = summarise_triaxial(p_.rows);
  v.push_back({"triaxial", "void_ratio_at_shear", p_.rows.empty() ? kNaN : p_.rows.front()[C::VoidRatio]});
  v.push_back({"triaxial", "peak_stress_ratio", t.peak_stress_ratio});
  v.push_back({"triaxial", "axial_strain_at_peak", t.strain_at_peak});
  v.push_back({"triaxial", "peak_friction_angle_deg", t.peak_friction_angle_deg});
  v.push_back({"triaxial", "critical_stress_ratio", t.critical_stress_ratio});
  v.push_back({"triaxial", "critical_friction_angle_deg", t.critical_friction_angle_deg});
  v.push_back({"triaxial", "critical_dilatancy_angle_deg", t.critical_dilatancy_angle_deg});
  v.push_back({"triaxial", "peak_dilatancy_angle_deg", t.peak_dilatancy_angle_deg});
  v.push_back({"triaxial", "e50_Pa", t.e50_Pa});
  v.push_back({"triaxial", "final_void_ratio", t.final_void_ratio});
  return v;
}

std::string TriaxialTest::status_line() const {
  if (p_.phase == TriaxialPhase::Prepare) return prep_->status_line();
  const double s1 = axial_stress(), s3 = cell_pressure();
  return fmt::format("axial strain {:.4f}  q {:.1f} kPa  p' {:.1f} kPa  sigma_3 {:.1f} kPa  eps_v {:.4f}  e {:.4f}",
                     axial_strain(), (s1 - s3) * 1e-3, (s1 + 2 * s3) / 3 * 1e-3, s3 * 1e-3, volumetric_strain(),
                     void_ratio());
}

std::string TriaxialTest::phase_note() const {
  if (p_.phase == TriaxialPhase::Prepare) return prep_->phase_note();
  if (p_.phase == TriaxialPhase::Isotropic)
    return fmt::format("prepared under the cap: e = {:.4f}; now the cap and the four sides held at {:.0f} kPa",
                       prep_->achieved_void_ratio(), spec_.consolidation.normal_stress * 1e-3);
  if (p_.phase == TriaxialPhase::Shear && !p_.rows.empty())
    return fmt::format("isotropically consolidated at {:.0f} kPa: e = {:.4f}; axial speed {:.3g} mm/s",
                       spec_.consolidation.normal_stress * 1e-3, p_.rows.front()[C::VoidRatio], axial_speed_ * 1e3);
  return "";
}

std::string TriaxialTest::result_line() const {
  const TriaxialSummary t = summarise_triaxial(p_.rows);
  return fmt::format("peak friction angle {:.1f} deg (q/p' {:.3f}) at axial strain {:.3f}; over the last fifth "
                     "{:.1f} deg with dilatancy {:.1f} deg (a critical state has 0); peak dilatancy angle {:.1f} deg; "
                     "E50 {:.3g} MPa",
                     t.peak_friction_angle_deg, t.peak_stress_ratio, t.strain_at_peak, t.critical_friction_angle_deg,
                     t.critical_dilatancy_angle_deg, t.peak_dilatancy_angle_deg, t.e50_Pa * 1e-6);
}

std::optional<BandGeometry> TriaxialTest::band_geometry() const {
  BandGeometry b;
  b.z_min = 0;
  b.z_max = p_.phase < TriaxialPhase::Shear ? cap_height() : p_.height_at_shear;
  b.layer = prep_->mean_diameter();
  b.direction = Vec3::UnitX();
  b.strain = 0;  // no imposed shear displacement: the band columns stay empty
  b.length = spec_.box.length;
  return b;
}

std::vector<std::uint8_t> TriaxialTest::save() const {
  ByteWriter b;
  prep_->save(b);
  b.i32(static_cast<std::int32_t>(p_.phase));
  p_.rest.save(b);
  cap_servo_.save(b);
  for (const StressServo& s : side_servos_) s.save(b);
  b.f64(p_.height_at_shear), b.f64(p_.volume_at_shear), b.f64(p_.next_sample_strain);
  for (double x : p_.side_stress_sum) b.f64(x);
  b.i32(p_.steps_since_sample);
  b.i64(p_.phase_start_step), b.i64(p_.shear_start_step);
  b.u64(p_.rows.size());
  for (const auto& r : p_.rows) b.f64s(r);
  save_bodies(b, p_.reference);
  return std::move(b.bytes);
}

void TriaxialTest::load(std::span<const std::uint8_t> bytes) {
  ByteReader r(bytes, "the triaxial protocol state", " Start the run again without --resume.");
  prep_->load(r);
  const std::int32_t phase = r.i32();
  if (phase < 0 || phase > static_cast<int>(TriaxialPhase::Done)) r.corrupted("an unknown phase");
  p_.phase = static_cast<TriaxialPhase>(phase);
  p_.rest.load(r);
  cap_servo_.load(r);
  for (StressServo& s : side_servos_) s.load(r);
  p_.height_at_shear = r.f64(), p_.volume_at_shear = r.f64(), p_.next_sample_strain = r.f64();
  for (double& x : p_.side_stress_sum) x = r.f64();
  p_.steps_since_sample = r.i32();
  p_.phase_start_step = r.i64(), p_.shear_start_step = r.i64();
  p_.rows.resize(r.count(8));
  for (auto& row : p_.rows) row = r.f64s();
  p_.reference = load_bodies(r);
  r.expect_end();
}

}  // namespace grainlab
