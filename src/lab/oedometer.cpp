// The oedometer protocol, its measurements and its summary (definitions in
// oedometer.h).
#include "lab/oedometer.h"

#include "core/error.h"
#include "core/line_fit.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace grainlab {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr std::int64_t kMaxStageSteps = 400000;  // as the direct shear's phases

using C = OedometerColumn;

}  // namespace

const std::vector<std::string>& oedometer_series_columns() {
  static const std::vector<std::string> columns = {
      "time_s",          "stage",           "target_stress_Pa", "vertical_stress_Pa", "floor_stress_Pa",
      "lateral_stress_Pa", "K0",            "vertical_strain",  "cap_height_m",       "void_ratio",
      "constrained_modulus_Pa", "coordination_number", "kinetic_energy_J", "unbalanced_force_ratio"};
  return columns;
}

OedometerSummary summarise_oedometer(const std::vector<std::vector<double>>& all_rows) {
  OedometerSummary s;
  s.swelling_index = s.modulus_stress_exponent = kNaN;
  // Each stage's last row (a constant-rate run records several per stage),
  // with M recomputed between them.
  std::vector<std::vector<double>> rows;
  for (std::size_t i = 0; i < all_rows.size(); ++i)
    if (i + 1 == all_rows.size() || all_rows[i + 1][C::Stage] != all_rows[i][C::Stage]) rows.push_back(all_rows[i]);
  for (std::size_t i = 0; i < rows.size(); ++i)
    rows[i][C::Modulus] = i == 0 ? kNaN
                              : (rows[i][C::Vertical] - rows[i - 1][C::Vertical]) / (rows[i][C::Strain] - rows[i - 1][C::Strain]);
  if (rows.size() < 2) return s;
  s.final_void_ratio = rows.back()[C::VoidRatio];
  // The largest stress and the loading increments before it (each above the last).
  std::size_t top = 0;
  for (std::size_t i = 1; i < rows.size(); ++i)
    if (rows[i][C::Target] > rows[top][C::Target]) top = i;
  s.max_stress = rows[top][C::Vertical];
  s.k0_at_max_stress = rows[top][C::K0];
  s.modulus_at_max_stress = rows[top][C::Modulus];
  const auto index = [&](std::size_t a, std::size_t b) {  // -de / dlog10(sigma) from row a to row b
    return -(rows[b][C::VoidRatio] - rows[a][C::VoidRatio]) / std::log10(rows[b][C::Vertical] / rows[a][C::Vertical]);
  };
  std::size_t first_unload = rows.size();
  for (std::size_t i = 1; i < rows.size(); ++i)
    if (rows[i][C::Target] < rows[i - 1][C::Target]) {
      first_unload = i;
      break;
    }
  const std::size_t last_load = first_unload - 1;  // the row before the first unloading
  s.compression_index = last_load >= 1 ? index(last_load - 1, last_load) : kNaN;
  // Unloading branch after the largest stress: down to its lowest stress.
  std::size_t low = top;
  for (std::size_t i = top + 1; i < rows.size() && rows[i][C::Target] < rows[i - 1][C::Target]; ++i) low = i;
  if (low > top) s.swelling_index = index(top, low);
  // n of M ~ sigma^n: least squares of log M on the log mean stress of each
  // loading increment but the first, which starts from the preparation's
  // stress state (K0 0.73-0.90 after consolidation) and rearranges it.
  LineFit fit;
  for (std::size_t i = 2; i <= last_load; ++i) {
    const double m = rows[i][C::Modulus];
    if (m > 0) fit.add(std::log(0.5 * (rows[i][C::Vertical] + rows[i - 1][C::Vertical])), std::log(m));
  }
  s.modulus_stress_exponent = fit.slope();  // NaN below two increments
  return s;
}

OedometerTest::OedometerTest(const LabSpec& spec)
    : OedometerTest(spec, std::make_unique<SpecimenPreparation>(preparation_spec(spec))) {}

OedometerTest::OedometerTest(const LabSpec& spec, std::unique_ptr<SpecimenPreparation> preparation)
    : ClosedBoxTest(spec, std::move(preparation)), constant_rate_(spec.settings<OedometerSpec>().loading == "constant-rate") {
  // Runs after the preparation's servo, which is idle once it is done.
  world().add_controller([this](World& w, double dt) {
    if (p_.phase == OedometerPhase::Load && !constant_rate()) servo_.control(w, dt);
  });
}

double OedometerTest::stage_stress(int stage) const {
  return stage == 0 ? spec_.consolidation.normal_stress : spec_.settings<OedometerSpec>().stresses[static_cast<std::size_t>(stage - 1)];
}

double OedometerTest::cap_height() const { return world().state.walls[Cap].x.z(); }

double OedometerTest::vertical_stress() const { return world().state.walls[Cap].force.z() / area(); }

double OedometerTest::floor_stress() const { return -world().state.walls[ShearBoxWall::Floor].force.z() / area(); }

double OedometerTest::lateral_stress() const {
  // The grains push the -x walls towards -x and the +x walls towards +x.
  const auto& walls = world().state.walls;
  const double fx = walls[LowerXp].force.x() + walls[UpperXp].force.x() - walls[LowerXm].force.x() -
                    walls[UpperXm].force.x();
  const double fy = walls[LowerYp].force.y() + walls[UpperYp].force.y() - walls[LowerYm].force.y() -
                    walls[UpperYm].force.y();
  const double h = cap_height();
  return 0.25 * (fx / (spec_.box.width * h) + fy / (spec_.box.length * h));
}

double OedometerTest::vertical_strain() const {
  if (p_.phase == OedometerPhase::Prepare) return 0;
  return (p_.height_at_load - cap_height()) / p_.height_at_load;
}

double OedometerTest::specimen_volume() const { return area() * cap_height(); }

int OedometerTest::phase_index() const {
  // deposit 0, compact 1, consolidate 2 (the preparation's), load 3, done 4.
  return p_.phase == OedometerPhase::Prepare ? static_cast<int>(prep_->phase()) : 2 + static_cast<int>(p_.phase);
}

std::string OedometerTest::phase_name() const {
  switch (p_.phase) {
    case OedometerPhase::Prepare: return prep_->phase_name();
    case OedometerPhase::Load: return "load";
    case OedometerPhase::Done: return "done";
  }
  return "?";
}

double OedometerTest::progress() const {
  if (p_.phase == OedometerPhase::Done) return 1;
  if (p_.phase == OedometerPhase::Prepare) return 0;
  return static_cast<double>(p_.stage - 1) / stages();
}

void OedometerTest::start_loading() {
  p_.phase = OedometerPhase::Load;
  p_.load_start_step = world().state.step;
  p_.height_at_load = cap_height();
  p_.reference = world().state.bodies;
  set_cap_speed();
  p_.stage = 0;
  record_row();  // the consolidated specimen
  start_stage(1);
}

void OedometerTest::start_stage(int stage) {
  p_.stage = stage;
  p_.stage_start_step = world().state.step;
  p_.rest.reset();
  servo_ = stage_servo(stage);
  if (constant_rate()) {  // down to load, up to unload
    const bool unload = stage_stress(stage) < stage_stress(stage - 1);
    world().state.walls[Cap].v = Vec3(0, 0, unload ? cap_speed_ : -cap_speed_);
  }
}

StressServo OedometerTest::stage_servo(int stage) const {
  // At most the constant-rate speed: each stage is loaded quasi-statically.
  return StressServo(Cap, area(), stage_stress(stage), cap_speed_);
}

void OedometerTest::set_cap_speed() {
  // I = (v / H_0) d sqrt(rho S / sigma_0) at the consolidation stress sigma_0.
  const double rho = spec_.material.grain.density * world().model.density_scale;
  cap_speed_ = spec_.numerics.inertial_number * p_.height_at_load /
               (prep_->mean_diameter() * std::sqrt(rho / stage_stress(0)));
}

bool OedometerTest::stage_reached() const {
  const double target = stage_stress(p_.stage);
  return target < stage_stress(p_.stage - 1) ? vertical_stress() <= target : vertical_stress() >= target;
}

bool OedometerTest::advance_constant_rate(int max_steps) {
  World& w = world();
  constexpr double kRowFactor = 1.0471285480508996;  // 10^(1/50): 50 rows per decade of stress
  for (int i = 0; i < max_steps; ++i) {
    w.step(time_step());
    if (stage_reached()) {
      record_row();
      if (p_.stage == stages()) {
        w.state.walls[Cap].v.setZero();
        p_.phase = OedometerPhase::Done;
        return false;
      }
      start_stage(p_.stage + 1);
      return true;
    }
    const double sv = vertical_stress();
    if (sv > 0 && (sv >= kRowFactor * p_.last_row_stress || sv * kRowFactor <= p_.last_row_stress)) {
      record_row();
      return true;
    }
  }
  return true;
}

bool OedometerTest::stage_at_rest() {
  const auto& c = spec_.consolidation;
  const bool calm =
      std::abs(vertical_stress() / stage_stress(p_.stage) - 1) <= c.tolerance && kinetic_small_against_elastic(world());
  const bool rest = p_.rest.check(calm, world(), c.max_unbalanced);
  const std::int64_t in_stage = world().state.step - p_.stage_start_step;
  if (!rest && in_stage > kMaxStageSteps)
    throw RunError(fmt::format(
        "oedometer stage {} ({:.4g} Pa) did not come to rest in {} steps (cap stress {:.4g} Pa, kinetic energy "
        "{:.3g} J): try a smaller time step, more damping (lower restitution) or a larger "
        "consolidation.max_unbalanced",
        p_.stage, stage_stress(p_.stage), in_stage, vertical_stress(), world().kinetic_energy()));
  return rest;
}

bool OedometerTest::advance(int max_steps) {
  if (p_.phase == OedometerPhase::Done) return false;
  if (p_.phase == OedometerPhase::Prepare) {
    if (prepare(max_steps)) start_loading();
    return true;  // a preparation phase ended, or the steps are done
  }
  if (constant_rate()) return advance_constant_rate(max_steps);
  World& w = world();
  for (int i = 0; i < max_steps; ++i) {
    w.step(time_step());
    p_.rest.add(w.body_forces());
    if (w.state.step % kCheckEvery != 0 || !stage_at_rest()) continue;
    record_row();
    if (p_.stage == stages()) {
      p_.phase = OedometerPhase::Done;
      return false;
    }
    start_stage(p_.stage + 1);
    return true;  // a row was recorded
  }
  return true;
}

void OedometerTest::record_row() {
  const World& w = world();
  const double sv = vertical_stress(), eps = vertical_strain();
  double modulus = kNaN;
  if (!p_.rows.empty()) {
    const auto& prev = p_.rows.back();
    modulus = (sv - prev[C::Vertical]) / (eps - prev[C::Strain]);
  }
  const double sh = lateral_stress();
  std::vector<double> row = {w.state.time,
                             static_cast<double>(p_.stage),
                             stage_stress(p_.stage),
                             sv,
                             floor_stress(),
                             sh,
                             sv > 0 ? sh / sv : kNaN,
                             eps,
                             cap_height(),
                             void_ratio(),
                             modulus,
                             prep_->coordination_number(),
                             w.kinetic_energy(),
                             unbalanced_force_ratio(w)};
  observe(row);
  p_.rows.push_back(std::move(row));
  p_.last_row_stress = sv;
}

std::vector<SummaryValue> OedometerTest::summary() const {
  std::vector<SummaryValue> v = prep_->summary();
  const OedometerSummary o = summarise_oedometer(p_.rows);
  v.push_back({"oedometer", "compression_index", o.compression_index});
  v.push_back({"oedometer", "swelling_index", o.swelling_index});
  v.push_back({"oedometer", "max_stress_Pa", o.max_stress});
  v.push_back({"oedometer", "K0_at_max_stress", o.k0_at_max_stress});
  v.push_back({"oedometer", "constrained_modulus_at_max_stress_Pa", o.modulus_at_max_stress});
  v.push_back({"oedometer", "modulus_stress_exponent", o.modulus_stress_exponent});
  v.push_back({"oedometer", "final_void_ratio", o.final_void_ratio});
  return v;
}

std::string OedometerTest::status_line() const {
  if (p_.phase == OedometerPhase::Prepare) return prep_->status_line();
  return fmt::format("stage {}/{}  target {:.1f} kPa  sigma_v {:.1f} kPa  K0 {:.3f}  strain {:.5f}  e {:.4f}",
                     p_.stage, stages(), stage_stress(p_.stage) * 1e-3, vertical_stress() * 1e-3,
                     vertical_stress() > 0 ? lateral_stress() / vertical_stress() : 0.0, vertical_strain(),
                     void_ratio());
}

std::string OedometerTest::phase_note() const {
  if (p_.phase == OedometerPhase::Prepare) return prep_->phase_note();
  if (p_.phase != OedometerPhase::Load || p_.rows.empty()) return "";
  const std::string how = constant_rate() ? fmt::format("at a constant cap speed of {:.3g} mm/s", cap_speed_ * 1e3)
                                           : std::string("each held to rest");
  return fmt::format("consolidated under {:.0f} kPa: e = {:.4f}, K0 = {:.3f}; now {} stages, {}",
                     stage_stress(0) * 1e-3, p_.rows.front()[C::VoidRatio], p_.rows.front()[C::K0], stages(), how);
}

std::string OedometerTest::result_line() const {
  const OedometerSummary o = summarise_oedometer(p_.rows);
  return fmt::format("Cc {:.4f}, Cs {:.4f}; at {:.0f} kPa K0 {:.3f} and constrained modulus {:.3g} MPa; M ~ "
                     "sigma^{:.2f}",
                     o.compression_index, o.swelling_index, o.max_stress * 1e-3, o.k0_at_max_stress,
                     o.modulus_at_max_stress * 1e-6, o.modulus_stress_exponent);
}

std::optional<BandGeometry> OedometerTest::band_geometry() const {
  // No imposed shear: a profile of horizontal displacement, for the record.
  BandGeometry b;
  b.z_min = 0;
  b.z_max = p_.phase == OedometerPhase::Prepare ? cap_height() : p_.height_at_load;
  b.layer = prep_->mean_diameter();
  b.direction = Vec3::UnitX();
  b.strain = 0;
  b.length = spec_.box.length;
  return b;
}

std::vector<std::uint8_t> OedometerTest::save() const {
  ByteWriter b;
  prep_->save(b);
  b.i32(static_cast<std::int32_t>(p_.phase));
  b.i32(p_.stage);
  b.f64(p_.height_at_load), b.f64(p_.last_row_stress);
  p_.rest.save(b);
  servo_.save(b);
  b.i64(p_.load_start_step), b.i64(p_.stage_start_step);
  b.u64(p_.rows.size());
  for (const auto& r : p_.rows) b.f64s(r);
  save_bodies(b, p_.reference);
  return std::move(b.bytes);
}

void OedometerTest::load(std::span<const std::uint8_t> bytes) {
  ByteReader r(bytes, "the oedometer protocol state", " Start the run again without --resume.");
  prep_->load(r);
  const std::int32_t phase = r.i32();
  if (phase < 0 || phase > static_cast<int>(OedometerPhase::Done)) r.corrupted("an unknown phase");
  p_.phase = static_cast<OedometerPhase>(phase);
  p_.stage = r.i32();
  if (p_.stage < 0 || p_.stage > stages()) r.corrupted("a stage outside the schedule");
  p_.height_at_load = r.f64(), p_.last_row_stress = r.f64();
  if (p_.phase != OedometerPhase::Prepare) set_cap_speed();  // the cap's velocity is the world's, restored
  if (p_.phase == OedometerPhase::Load) servo_ = stage_servo(p_.stage);  // its target; its integral next
  p_.rest.load(r);
  servo_.load(r);
  p_.load_start_step = r.i64(), p_.stage_start_step = r.i64();
  p_.rows.resize(r.count(8));
  for (auto& row : p_.rows) row = r.f64s();
  p_.reference = load_bodies(r);
  r.expect_end();
}

}  // namespace grainlab
