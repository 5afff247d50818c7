// The direct shear protocol (see direct_shear.h for the box, the phases, the
// servo and the measured quantities).
#include "lab/direct_shear.h"

#include "core/error.h"
#include "core/rng.h"
#include "lab/grain_library.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>

namespace grainlab {

namespace {

constexpr double kSlab = 2.5e-3;          // m, thickness of the box slabs
constexpr double kDepositionGravity = 100;  // g while raining: a numerical preparation step
constexpr double kServoAlpha = 0.05;
constexpr double kServoIntegral = 0.005;  // per step: integral time 200 steps (beta = alpha / 10)
constexpr int kCheckEvery = 50;            // steps between rest checks
constexpr int kCalmChecks = 20;            // consecutive calm checks = at rest

// Byte writer/reader for the protocol state.
struct Bytes {
  std::vector<std::uint8_t> data;
  template <typename T> void put(const T& v) {
    const auto* p = reinterpret_cast<const std::uint8_t*>(&v);
    data.insert(data.end(), p, p + sizeof(T));
  }
};
struct Reader {
  std::span<const std::uint8_t> data;
  std::size_t at = 0;
  template <typename T> T get() {
    if (at + sizeof(T) > data.size()) throw RunError("checkpoint: protocol state is truncated");
    T v;
    std::memcpy(&v, data.data() + at, sizeof(T));
    at += sizeof(T);
    return v;
  }
};

}  // namespace

const char* shear_phase_name(ShearPhase p) {
  switch (p) {
    case ShearPhase::Deposit: return "deposit";
    case ShearPhase::Compact: return "compact";
    case ShearPhase::Consolidate: return "consolidate";
    case ShearPhase::Shear: return "shear";
    case ShearPhase::Done: return "done";
  }
  return "?";
}

const std::vector<std::string>& shear_series_columns() {
  static const std::vector<std::string> columns = {
      "time_s",          "shear_strain",      "horizontal_displacement_m", "vertical_displacement_m",
      "shear_force_N",   "normal_force_N",    "normal_stress_Pa",          "stress_ratio",
      "friction_angle_deg", "void_ratio",     "coordination_number",       "kinetic_energy_J",
      "unbalanced_force_ratio", "inertial_number"};
  return columns;
}

DirectShearTest::DirectShearTest(const DirectShearSpec& spec) : spec_(spec) {
  Model& m = world_.model;
  m.law = spec.material.law;
  Material grain = spec.material.grain;
  grain.friction = spec.specimen.deposition_friction;
  grain_material_ = m.add_material(grain);
  Material wall = spec.material.grain;
  wall.name = "wall";
  wall.friction = spec.material.wall_friction;
  // Friction mixes by the minimum (material.h): lubricated walls stay lubricated.
  wall_material_ = m.add_material(wall);

  const std::vector<Index> shapes = add_grain_shapes(m, spec.grains, spec.seed);
  double mean_volume = 0, max_bound = 0;
  for (Index s : shapes) {
    mean_volume += m.shapes[s].volume / shapes.size();
    max_bound = std::max(max_bound, m.shapes[s].bounding_radius);
  }
  mean_diameter_ = std::cbrt(6.0 * mean_volume / std::numbers::pi);

  // As many grains as fill the box at the target void ratio.
  const double L = spec.box.length, W = spec.box.width, H = spec.box.height;
  const double e_target = spec.target_void_ratio();
  const int count = static_cast<int>(std::lround(L * W * H / ((1 + e_target) * mean_volume)));
  const double pitch = 2.0 * max_bound * 1.05;
  const int nx = static_cast<int>(L / pitch), ny = static_cast<int>(W / pitch);
  if (nx < 1 || ny < 1)
    input_error("box {} x {} mm is smaller than one grain ({:.3f} mm across): make the box larger "
                "or the grains smaller",
                L * 1e3, W * 1e3, pitch * 1e3);
  Rng rng(spec.seed);
  const double sx = L / nx, sy = W / ny;
  for (int i = 0; i < count; ++i) {
    const int layer = i / (nx * ny), in_layer = i % (nx * ny);
    const Vec3 x(-0.5 * L + (in_layer % nx + 0.5) * sx, -0.5 * W + (in_layer / nx + 0.5) * sy,
                 (layer + 0.5) * pitch);
    const Index shape = shapes[rng.next_u64() % shapes.size()];
    world_.add_body(shape, grain_material_, 1.0, x, rng.rotation(), 1e-3 * rng.unit_vector());
    solid_volume_ += m.shapes[shape].volume;
    mean_mass_ += m.bodies.back().gravity_mass / count;
  }
  fill_top_ = (count / (nx * ny) + 1) * pitch + pitch;

  // Density scaling (automatic: S = 100). At a fixed inertial number it does
  // not change the number of shear steps (dt and the shear speed both grow
  // with sqrt(S)); it shortens deposition and consolidation, which last a
  // fixed simulated time.
  m.density_scale = spec.numerics.density_scaling > 0 ? spec.numerics.density_scaling : 100.0;
  m.rescale_bodies();
  build_walls();

  const double critical = world_.critical_time_step();
  dt_ = spec.numerics.time_step > 0 ? spec.numerics.time_step : spec.numerics.time_step_fraction * critical;
  if (dt_ > critical)
    input_error("numerics.time_step = {:.3g} s is above the critical step {:.3g} s of these grains: "
                "use at most {:.3g} s, or raise numerics.density_scaling (the critical step grows "
                "with its square root)",
                dt_, critical, critical);
  // Shear speed for the requested inertial number I = (v / H) d sqrt(rho S / sigma).
  const double rho = spec.material.grain.density * m.density_scale;
  shear_speed_ = spec.shear.speed > 0
                     ? spec.shear.speed
                     : spec.numerics.inertial_number * H /
                           (mean_diameter_ * std::sqrt(rho / spec.consolidation.normal_stress));
  cap_speed_limit_ = 2e-4 * mean_diameter_ / dt_;
  world_.add_controller([this](World& w, double dt) { servo(w, dt); });
  enter(ShearPhase::Deposit);
}

void DirectShearTest::build_walls() {
  const double L = spec_.box.length, W = spec_.box.width, H = spec_.box.height, gap = spec_.box.gap;
  const double t = kSlab;
  world_.add_plane(Vec3::Zero(), Vec3::UnitZ(), wall_material_, "floor");
  const double lower_top = 0.5 * H - 0.5 * gap, upper_bottom = 0.5 * H + 0.5 * gap;
  const double top = fill_top_ + t;
  for (int half = 0; half < 2; ++half) {
    const double z0 = half == 0 ? -t : upper_bottom, z1 = half == 0 ? lower_top : top;
    const double zc = 0.5 * (z0 + z1), hz = 0.5 * (z1 - z0);
    const std::string name = half == 0 ? "lower" : "upper";
    world_.add_box_wall(Vec3(-0.5 * L - 0.5 * t, 0, zc), Vec3(0.5 * t, 0.5 * W + t, hz), Quat::Identity(),
                        wall_material_, name + "-x");
    world_.add_box_wall(Vec3(0.5 * L + 0.5 * t, 0, zc), Vec3(0.5 * t, 0.5 * W + t, hz), Quat::Identity(),
                        wall_material_, name + "+x");
    world_.add_box_wall(Vec3(0, -0.5 * W - 0.5 * t, zc), Vec3(0.5 * L + t, 0.5 * t, hz), Quat::Identity(),
                        wall_material_, name + "-y");
    world_.add_box_wall(Vec3(0, 0.5 * W + 0.5 * t, zc), Vec3(0.5 * L + t, 0.5 * t, hz), Quat::Identity(),
                        wall_material_, name + "+y");
  }
  world_.add_plane(Vec3(0, 0, top - 0.5 * t), -Vec3::UnitZ(), wall_material_, "cap");
}

void DirectShearTest::enter(ShearPhase p) {
  progress_.phase = p;
  progress_.calm_checks = 0;
  progress_.phase_start_step[static_cast<int>(p)] = world_.state.step;
  Model& m = world_.model;
  const double g = 9.81;
  switch (p) {
    case ShearPhase::Deposit:
      m.gravity = Vec3(0, 0, -kDepositionGravity * g * m.density_scale);
      break;
    case ShearPhase::Compact: {
      m.gravity = Vec3(0, 0, -g);
      // Bring the cap down to just above the highest grain.
      double top = 0;
      for (std::size_t i = 0; i < m.bodies.size(); ++i)
        top = std::max(top, world_.state.bodies[i].x.z() + m.bodies[i].bounding_radius);
      world_.state.walls[wall(Cap)].x.z() = top + 0.05 * mean_diameter_;
      break;
    }
    case ShearPhase::Consolidate:
      m.materials[grain_material_].friction = spec_.material.grain.friction;
      m.finalize();
      break;
    case ShearPhase::Shear:
      progress_.cap_z_at_shear = world_.state.walls[wall(Cap)].x.z();
      progress_.upper_x_at_shear = world_.state.walls[wall(UpperXm)].x.x();
      progress_.next_sample_strain = 0;
      progress_.reference = world_.state.bodies;
      for (int r = UpperXm; r <= UpperYp; ++r) world_.state.walls[r].v = Vec3(shear_speed_, 0, 0);
      world_.state.walls[wall(Cap)].v.x() = shear_speed_;
      record_sample();
      break;
    case ShearPhase::Done:
      for (int r = UpperXm; r <= Cap; ++r) world_.state.walls[r].v.setZero();
      break;
  }
}

void DirectShearTest::servo(World& w, double dt) {
  const ShearPhase p = progress_.phase;
  if (p == ShearPhase::Deposit || p == ShearPhase::Done) return;
  WallState& cap = w.state.walls[wall(Cap)];
  double k_cap = 0;
  const double tangent = w.model.law == ContactLaw::Hooke ? 1.0 : 1.5;
  for (const PairContact& pc : w.state.wall_pairs)
    if (pc.a == wall(Cap) && in_contact(pc) && pc.geo.depth > 0) k_cap += tangent * pc.normal_force / pc.geo.depth;
  if (k_cap <= 0) {
    cap.v.z() = -cap_speed_limit_;  // not touching yet: come down
    progress_.servo_integral = 0;
    return;
  }
  const double gain = kServoAlpha * box_area() / (k_cap * dt);
  const double error = normal_stress() - spec_.consolidation.normal_stress;
  const double v = gain * (error + progress_.servo_integral);
  cap.v.z() = std::clamp(v, -cap_speed_limit_, cap_speed_limit_);
  // Integral action only while the cap is free to follow (no wind-up at the clamp).
  if (cap.v.z() == v) progress_.servo_integral += kServoIntegral * error;
}

bool DirectShearTest::at_rest(bool strict) const {
  const double sigma = spec_.consolidation.normal_stress;
  const double tolerance = strict ? spec_.consolidation.tolerance : std::max(spec_.consolidation.tolerance, 0.05);
  if (std::abs(normal_stress() / sigma - 1) > tolerance) return false;
  // Kinetic energy small against the elastic energy stored in the contacts
  // (Hertz: (2/5) f delta per contact).
  double elastic = 0;
  for (const auto* list : {&world_.state.pairs, &world_.state.wall_pairs})
    for (const PairContact& pc : *list)
      if (in_contact(pc)) elastic += 0.4 * pc.normal_force * pc.geo.depth;
  return world_.kinetic_energy() < 1e-2 * elastic;
}

bool DirectShearTest::advance(int max_steps) {
  for (int i = 0; i < max_steps && progress_.phase != ShearPhase::Done; ++i) {
    world_.step(dt_);
    const ShearPhase p = progress_.phase;
    if (p == ShearPhase::Shear) {
      const bool sampled = shear_strain() + 1e-12 >= progress_.next_sample_strain;
      if (sampled) record_sample();
      if (shear_strain() >= spec_.shear.final_strain) {
        enter(ShearPhase::Done);
        return false;
      }
      if (sampled) return true;
      continue;
    }
    // Resultant force on each grain summed over the check window: its mean
    // is the static imbalance, free of the contacts' ringing.
    auto& sum = progress_.force_sum;
    const auto& f = world_.body_forces();
    sum.resize(f.size(), Vec3::Zero());
    for (std::size_t k = 0; k < f.size(); ++k) sum[k] += f[k];
    ++progress_.window_steps;
    if (world_.state.step % kCheckEvery != 0) continue;
    const std::int64_t in_phase = world_.state.step - progress_.phase_start_step[static_cast<int>(p)];
    // Deposit: settled when the kinetic energy is below the work of lifting
    // every grain by a thousandth of its diameter against the deposition
    // gravity (inertial masses on both sides). The compaction that follows
    // finishes the settling under the cap; faceted grains with little friction
    // keep a faint jitter that a stricter bound would wait on for ever.
    const double lift = mean_mass_ * world_.model.density_scale * kDepositionGravity * 9.81 * mean_diameter_;
    const bool calm = p == ShearPhase::Deposit
                          ? world_.kinetic_energy() < 1e-3 * lift * world_.model.bodies.size()
                          : at_rest(p == ShearPhase::Consolidate);
    progress_.calm_checks = calm ? progress_.calm_checks + 1 : 0;
    // The consolidation also needs the static balance: each grain's resultant
    // averaged over the whole calm run (kCalmChecks x kCheckEvery steps). The
    // window spans the run rather than one check interval because the packing
    // rings in collective modes longer than 50 steps: in the tiny test box the
    // ratio averaged over 50 steps swings up to 0.014 while over 1000 steps
    // it is 0.0008.
    const double averaged_unbalanced = averaged_unbalanced_force_ratio();
    const int window = progress_.window_steps;
    if (progress_.calm_checks >= kCalmChecks && p == ShearPhase::Consolidate &&
        averaged_unbalanced > spec_.consolidation.max_unbalanced)
      progress_.calm_checks = 0;
    if (progress_.calm_checks == 0 || progress_.calm_checks >= kCalmChecks) {
      std::fill(sum.begin(), sum.end(), Vec3::Zero());
      progress_.window_steps = 0;
    }
    if (progress_.calm_checks < kCalmChecks) {
      if (in_phase > 400000)
        throw RunError(fmt::format(
            "the {} phase did not come to rest in {} steps (normal stress {:.4g} Pa, unbalanced force "
            "ratio {:.3g} averaged over {} steps, kinetic energy {:.3g} J): try a smaller time step, more "
            "damping (lower restitution) or a larger consolidation.max_unbalanced",
            shear_phase_name(p), in_phase, normal_stress(), averaged_unbalanced, window,
            world_.kinetic_energy()));
      continue;
    }
    if (p == ShearPhase::Deposit) {
      enter(ShearPhase::Compact);
    } else if (p == ShearPhase::Compact) {
      progress_.compacted_void_ratio = void_ratio();
      const double target = spec_.target_void_ratio();
      if (std::abs(progress_.compacted_void_ratio - target) > spec_.specimen.tolerance) {
        throw RunError(fmt::format(
            "specimen preparation reached void ratio e = {:.3f} (Dr = {:.0f} %) under {:.0f} kPa, but "
            "the target is e = {:.3f} +- {:.3f} (Dr = {:.0f} %). {}",
            progress_.compacted_void_ratio, 100 * achieved_relative_density(),
            spec_.consolidation.normal_stress * 1e-3, target, spec_.specimen.tolerance,
            100 * spec_.specimen.relative_density,
            progress_.compacted_void_ratio > target
                ? (spec_.specimen.deposition_friction > 0
                       ? "Lower specimen.deposition_friction for a denser specimen, or set a reachable target."
                       : "Deposition is already frictionless, the densest this procedure makes: these "
                         "grains in this box do not pack that densely. Raise specimen.e_min/e_max or "
                         "set specimen.void_ratio to a reachable value.")
                : "Raise specimen.deposition_friction for a looser specimen."));
      }
      enter(ShearPhase::Consolidate);
    } else if (p == ShearPhase::Consolidate) {
      enter(ShearPhase::Shear);
    }
    return true;  // a phase ended
  }
  return progress_.phase != ShearPhase::Done;
}

double DirectShearTest::shear_strain() const {
  if (progress_.phase < ShearPhase::Shear) return 0;
  return (world_.state.walls[wall(UpperXm)].x.x() - progress_.upper_x_at_shear) / spec_.box.length;
}

double DirectShearTest::normal_force() const { return world_.state.walls[wall(Cap)].force.z(); }
double DirectShearTest::normal_stress() const { return normal_force() / box_area(); }

double DirectShearTest::shear_force() const {
  double fx = 0;
  for (int r = UpperXm; r <= Cap; ++r) fx += world_.state.walls[r].force.x();
  return -fx;
}

double DirectShearTest::cap_displacement() const {
  if (progress_.phase < ShearPhase::Shear) return 0;
  return world_.state.walls[wall(Cap)].x.z() - progress_.cap_z_at_shear;
}

double DirectShearTest::void_ratio() const {
  const double v = box_area() * world_.state.walls[wall(Cap)].x.z();
  return (v - solid_volume_) / solid_volume_;
}

double DirectShearTest::achieved_relative_density() const {
  const auto& s = spec_.specimen;
  return (s.e_max - progress_.compacted_void_ratio) / (s.e_max - s.e_min);
}

double DirectShearTest::coordination_number() const {
  std::size_t contacts = 0;
  for (const PairContact& pc : world_.state.pairs) contacts += in_contact(pc);
  return 2.0 * contacts / std::max<std::size_t>(1, world_.model.bodies.size());
}

double DirectShearTest::unbalanced_force_ratio() const {
  double resultant = 0;
  for (const Vec3& f : world_.body_forces()) resultant += f.norm();
  return per_mean_contact_force(resultant / std::max<std::size_t>(1, world_.body_forces().size()));
}

double DirectShearTest::averaged_unbalanced_force_ratio() const {
  const auto& sum = progress_.force_sum;
  if (progress_.window_steps == 0 || sum.empty()) return unbalanced_force_ratio();
  double resultant = 0;
  for (const Vec3& f : sum) resultant += f.norm() / progress_.window_steps;
  return per_mean_contact_force(resultant / sum.size());
}

double DirectShearTest::per_mean_contact_force(double force) const {
  double contact = 0;
  std::size_t n_contacts = 0;
  for (const auto* list : {&world_.state.pairs, &world_.state.wall_pairs})
    for (const PairContact& pc : *list)
      if (in_contact(pc)) contact += pc.force.norm(), ++n_contacts;
  if (n_contacts == 0 || contact <= 0) return 1;
  return force / (contact / n_contacts);
}

double DirectShearTest::inertial_number() const {
  const double sigma = std::max(normal_stress(), 1e-9);
  const double rho = spec_.material.grain.density * world_.model.density_scale;
  return shear_speed_ / spec_.box.height * mean_diameter_ * std::sqrt(rho / sigma);
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
  std::vector<double> row = {world_.state.time, shear_strain(),
                             shear_strain() * spec_.box.length, cap_displacement(), F, N, normal_stress(),
                             ratio, std::atan(ratio) * 180 / std::numbers::pi, void_ratio(),
                             coordination_number(), world_.kinetic_energy(), unbalanced_force_ratio(),
                             inertial_number()};
  if (observer_) {
    const std::vector<double> extra = observer_(*this);
    if (extra.size() != observer_columns_.size())
      throw RunError(fmt::format("sample observer gave {} values for {} columns", extra.size(),
                                 observer_columns_.size()));
    row.insert(row.end(), extra.begin(), extra.end());
  }
  progress_.rows.push_back(std::move(row));
  while (progress_.next_sample_strain <= shear_strain() + 1e-12)
    progress_.next_sample_strain += spec_.output.strain_interval;
}

ShearSummary DirectShearTest::summary() const {
  ShearSummary s;
  const auto& rows = progress_.rows;
  if (rows.size() < 2) return s;
  constexpr int kStrain = 1, kDh = 2, kDv = 3, kRatio = 7, kPhi = 8, kE = 9;
  const double deg = 180 / std::numbers::pi;
  for (const auto& r : rows) {
    if (r[kPhi] > s.peak_friction_angle_deg) {
      s.peak_friction_angle_deg = r[kPhi];
      s.peak_stress_ratio = r[kRatio];
      s.strain_at_peak_friction = r[kStrain];
    }
  }
  // Dilation angle psi = atan(d(d_v)/d(d_h)) (Eq. 19), by central differences
  // over +-2 samples to tame the noise of single intervals.
  std::vector<double> psi(rows.size(), 0);
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const std::size_t lo = k >= 2 ? k - 2 : 0, hi = std::min(rows.size() - 1, k + 2);
    const double dh = rows[hi][kDh] - rows[lo][kDh];
    psi[k] = dh > 0 ? std::atan((rows[hi][kDv] - rows[lo][kDv]) / dh) * deg : 0;
    if (psi[k] > s.peak_dilation_angle_deg) {
      s.peak_dilation_angle_deg = psi[k];
      s.strain_at_peak_dilation = rows[k][kStrain];
    }
  }
  const double last = rows.back()[kStrain];
  int n = 0;
  for (std::size_t k = 0; k < rows.size(); ++k) {
    if (rows[k][kStrain] < 0.9 * last) continue;
    s.final_friction_angle_deg += rows[k][kPhi];
    s.final_dilation_angle_deg += psi[k];
    ++n;
  }
  if (n > 0) s.final_friction_angle_deg /= n, s.final_dilation_angle_deg /= n;
  s.final_void_ratio = rows.back()[kE];
  return s;
}

std::vector<std::uint8_t> DirectShearTest::save_progress() const {
  Bytes b;
  b.put(static_cast<std::int32_t>(progress_.phase));
  b.put(progress_.calm_checks);
  b.put(progress_.compacted_void_ratio);
  b.put(progress_.cap_z_at_shear);
  b.put(progress_.upper_x_at_shear);
  b.put(progress_.next_sample_strain);
  b.put(progress_.servo_integral);
  b.put(progress_.window_steps);
  b.put(static_cast<std::uint64_t>(progress_.force_sum.size()));
  for (const Vec3& f : progress_.force_sum)
    for (int k = 0; k < 3; ++k) b.put(f[k]);
  for (auto s : progress_.phase_start_step) b.put(s);
  b.put(static_cast<std::uint64_t>(progress_.rows.size()));
  for (const auto& r : progress_.rows) {
    b.put(static_cast<std::uint64_t>(r.size()));
    for (double v : r) b.put(v);
  }
  b.put(static_cast<std::uint64_t>(progress_.reference.size()));
  for (const BodyState& body : progress_.reference) {
    for (const Vec3* v : {&body.x, &body.v, &body.w})
      for (int k = 0; k < 3; ++k) b.put((*v)[k]);
    for (int k = 0; k < 4; ++k) b.put(body.q.coeffs()[k]);
  }
  // The model changes with the phase (gravity, friction): saved to be exact.
  for (int k = 0; k < 3; ++k) b.put(world_.model.gravity[k]);
  b.put(world_.model.materials[grain_material_].friction);
  return b.data;
}

void DirectShearTest::load_progress(std::span<const std::uint8_t> bytes) {
  Reader r{bytes};
  progress_.phase = static_cast<ShearPhase>(r.get<std::int32_t>());
  progress_.calm_checks = r.get<std::int32_t>();
  progress_.compacted_void_ratio = r.get<double>();
  progress_.cap_z_at_shear = r.get<double>();
  progress_.upper_x_at_shear = r.get<double>();
  progress_.next_sample_strain = r.get<double>();
  progress_.servo_integral = r.get<double>();
  progress_.window_steps = r.get<std::int32_t>();
  progress_.force_sum.resize(r.get<std::uint64_t>());
  for (Vec3& f : progress_.force_sum)
    for (int k = 0; k < 3; ++k) f[k] = r.get<double>();
  for (auto& s : progress_.phase_start_step) s = r.get<std::int64_t>();
  progress_.rows.resize(r.get<std::uint64_t>());
  for (auto& row : progress_.rows) {
    row.resize(r.get<std::uint64_t>());
    for (double& v : row) v = r.get<double>();
  }
  progress_.reference.resize(r.get<std::uint64_t>());
  for (BodyState& body : progress_.reference) {
    for (Vec3* v : {&body.x, &body.v, &body.w})
      for (int k = 0; k < 3; ++k) (*v)[k] = r.get<double>();
    for (int k = 0; k < 4; ++k) body.q.coeffs()[k] = r.get<double>();
  }
  for (int k = 0; k < 3; ++k) world_.model.gravity[k] = r.get<double>();
  world_.model.materials[grain_material_].friction = r.get<double>();
  world_.model.finalize();
  if (r.at != bytes.size()) throw RunError("checkpoint: protocol state has trailing bytes");
}

}  // namespace grainlab
