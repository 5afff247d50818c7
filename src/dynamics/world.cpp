// World: building (bodies, walls), phase overrides, and World::step, the
// recipe of the step's phases (world.h); the phases live in their own files
// (collision_driver.h, contact_forces.h, integrator.h, step_guard.h), and
// integration and bookkeeping, a few lines each, here.
//
// Determinism: every phase writes only its own slots in parallel and sums in
// a fixed order, so 1 and N threads give bit-identical states.
#include "dynamics/world.h"

#include "core/error.h"
#include "core/parallel.h"
#include "core/timer.h"
#include "dynamics/contact_forces.h"
#include "dynamics/integrator.h"
#include "dynamics/step_guard.h"
#include "dynamics/time_step.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace grainlab {

double kinetic_energy_of(const BodyModel& m, const BodyState& s) {
  const Vec3 w_local = s.q.conjugate() * s.w;
  return 0.5 * m.mass * s.v.squaredNorm() + 0.5 * w_local.dot(m.inertia.cwiseProduct(w_local));
}

Index World::add_body(Index shape, Index material, double scale, const Vec3& x, const Quat& q,
                      const Vec3& v, const Vec3& w) {
  if (model.materials.empty()) model.materials.push_back(Material{});
  model.bodies.push_back(model.make_body(shape, material, scale));
  BodyState s;
  s.x = x;
  s.q = q.normalized();
  s.v = v;
  s.w = w;
  state.bodies.push_back(s);
  prepared_ = false;
  return static_cast<Index>(model.bodies.size() - 1);
}

Index World::add_plane(const Vec3& point, const Vec3& normal, Index material, std::string name) {
  if (!(normal.norm() > 0)) input_error("plane wall '{}': normal must be non-zero", name);
  WallModel m;
  m.kind = WallModel::Kind::Plane;
  m.name = std::move(name);
  m.material = material;
  model.walls.push_back(m);
  WallState s;
  s.x = point;
  s.q = Quat::FromTwoVectors(Vec3::UnitZ(), normal.normalized());
  state.walls.push_back(s);
  prepared_ = false;
  return static_cast<Index>(model.walls.size() - 1);
}

Index World::add_box_wall(const Vec3& center, const Vec3& half, const Quat& q, Index material,
                          std::string name) {
  if (!(half.minCoeff() > 0)) input_error("box wall '{}': half extents must be positive", name);
  WallModel m;
  m.kind = WallModel::Kind::Box;
  m.name = std::move(name);
  m.material = material;
  m.half = half;
  model.walls.push_back(m);
  WallState s;
  s.x = center;
  s.q = q.normalized();
  state.walls.push_back(s);
  prepared_ = false;
  return static_cast<Index>(model.walls.size() - 1);
}

double World::critical_time_step() {
  model.finalize();
  return grainlab::critical_time_step(model, settings.expected_overlap_fraction).critical;
}

void World::set_overrides(PhaseOverrides o) {
  overrides_ = std::move(o);
  if (prepared_) mix_pair_table();
}

void World::mix_pair_table() {
  // Only friction is overridden, and it mixes by the minimum (the laws'
  // mix(), dynamics/laws/): the Model's table with that one coefficient recomputed.
  const std::size_t n = model.materials.size();
  std::vector<double> mu(n);
  for (std::size_t m = 0; m < n; ++m) mu[m] = model.materials[m].friction;
  for (const auto& [m, f] : overrides_.friction) {
    if (m < 0 || static_cast<std::size_t>(m) >= n)
      input_error("friction override for material {} but the model has {} materials", m, n);
    if (!(f >= 0 && std::isfinite(f))) input_error("friction override {} must be >= 0", f);
    mu[m] = f;
  }
  pair_table_.resize(n * n);
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = 0; b < n; ++b) {
      pair_table_[a * n + b] = model.pair(static_cast<Index>(a), static_cast<Index>(b));
      pair_table_[a * n + b].friction = std::min(mu[a], mu[b]);
    }
}

void World::prepare() {
  model.finalize();
  mix_pair_table();
  const std::size_t n = model.bodies.size();
  force_.assign(n, Vec3::Zero());
  torque_.assign(n, Vec3::Zero());
  motion_.assign(n, 0.0);
  if (settings.skin <= 0) {
    double r_min = std::numeric_limits<double>::infinity();
    for (const BodyModel& b : model.bodies) r_min = std::min(r_min, b.radius);
    settings.skin = std::isfinite(r_min) ? 0.2 * r_min : 1e-3;
  }
  // A later preparation follows a change of the model (bodies, walls, sizes):
  // find the wall candidates again. The first takes the State as given: a
  // restored checkpoint carries the wall poses its kept candidates were found
  // at, so a resumed run keeps the same list as the run that wrote it.
  if (prepared_once_) {
    state.wall_x_at_rebuild.clear();
    state.wall_q_at_rebuild.clear();
  }
  prepared_once_ = true;
  // No forced rebuild: a restored State carries its own candidate pairs, and
  // added bodies make x_at_rebuild the wrong size, which forces one.
  checked_dt_ = -1;
  prepared_ = true;
}

void World::step(double dt) {
  if (!prepared_) prepare();
  if (dt != checked_dt_) {
    require_stable_step(model, settings.expected_overlap_fraction, dt);
    checked_dt_ = dt;
  }
  const bool tuned = settings.threads <= 0;  // the tuner chooses the threads and times the step
  step_threads_ = choose_step_threads(settings, tuner_);
  const CollisionStep collide{model, state, settings, step_threads_, profile};
  const Stopwatch whole;
  Stopwatch sw;
  const auto lap = [&](Phase p) {
    profile[p] += sw.seconds();
    sw.reset();
  };
  collisions_.bounds(collide);
  lap(Phase::Bounds);
  collisions_.broadphase(collide);
  lap(Phase::Broadphase);
  // A world of spheres stepped serially makes its grain contacts inside the
  // forces phase, a batch at a time (collision_driver.h): the same bits, and
  // each contact is pushed and summed while in cache. Its narrowphase time is
  // then the walls' only, and the forces' holds the grain pairs' tests.
  const bool serial = resolve_threads(step_threads_) == 1 ||
                      static_cast<std::ptrdiff_t>(state.pairs.size()) < settings.serial_below;
  if (collisions_.compact() && serial) {
    collisions_.narrowphase_walls(collide);
    lap(Phase::Narrowphase);
    GrainContactSource source{&collisions_.begin_compact_contacts(),
                              [&](std::size_t want) { return collisions_.more_compact_contacts(collide, want); }};
    forces(dt, &source);
    collisions_.end_compact_contacts(collide);
    lap(Phase::Forces);
  } else {
    collisions_.narrowphase(collide);
    lap(Phase::Narrowphase);
    forces(dt, nullptr);
    lap(Phase::Forces);
  }
  for (auto& c : controllers_) c(*this, dt);
  lap(Phase::Controllers);
  integrate(dt);
  lap(Phase::Integrate);
  state.time += dt;
  ++state.step;
  bookkeeping();
  lap(Phase::Bookkeeping);
  ++profile.steps;
  if (tuned) tuner_.record(whole.seconds());
}

void World::forces(double dt, GrainContactSource* source) {
  contact_forces({model, state, pair_table_, gravity(), step_threads_, settings.serial_below, source}, dt, force_,
                 torque_);
}

void World::integrate(double dt) {
  const std::size_t n = state.bodies.size();
  // Bodies four at a time (fixed by index: the thread count changes
  // nothing): a block of four spheres turns their orientations in the lanes
  // of one register (integrator.h).
  const auto block = [&](std::ptrdiff_t k) {
    Quat* turned[4];
    Vec3 phi[4];
    int spheres = 0;
    const std::size_t end = std::min(n, 4 * static_cast<std::size_t>(k) + 4);
    for (std::size_t i = 4 * static_cast<std::size_t>(k); i < end; ++i) {
      BodyState& s = state.bodies[i];
      const BodyModel& m = model.bodies[i];
      s.v += (m.inv_mass * dt) * force_[i];
      s.x += dt * s.v;
      if (model.shapes[m.shape].isotropic) {
        spin_sphere(s.w, torque_[i], m.inv_inertia.x(), dt);
        turned[spheres] = &s.q, phi[spheres] = s.w * dt, ++spheres;
      } else {
        integrate_rotation(s.q, s.w, torque_[i], m.inertia, m.inv_inertia, dt);
      }
      motion_[i] = s.v.squaredNorm() + s.w.squaredNorm();
    }
    if (spheres == 4) {
      turn_spheres(turned, phi);
    } else {
      for (int j = 0; j < spheres; ++j) turn_sphere(*turned[j], phi[j]);
    }
  };
  // A faceted grain's rotation (implicit midpoint, four quaternion updates)
  // costs some 280 ns, ten times a sphere's: 256 of them outweigh waking a
  // thread, so only a world of spheres (whose pairs all take the compact path,
  // collision_driver.h) keeps the serial threshold.
  parallel_for(static_cast<std::ptrdiff_t>((n + 3) / 4), block, 64, step_threads_,
               collisions_.compact() ? settings.serial_below / 4 : 0);
  for (WallState& w : state.walls) w.x += dt * w.v;
}

void World::bookkeeping() {
  double motion = 0;
  for (double m : motion_) motion += m;
  profile.contacts += static_cast<std::int64_t>(contact_count());
  if (!std::isfinite(motion)) {
    for (std::size_t i = 0; i < state.bodies.size(); ++i) {
      const BodyState& b = state.bodies[i];
      if (!b.x.allFinite() || !b.v.allFinite() || !b.w.allFinite())
        throw RunError(fmt::format(
            "step {} (t = {:.6g} s): grain {} has a non-finite position, velocity or angular velocity; the "
            "run went unstable. Reduce the time step or check the contact stiffness",
            state.step, state.time, i));
    }
    throw RunError(fmt::format("step {}: the grains' speeds overflow; the run went unstable", state.step));
  }
}

double World::kinetic_energy() const {
  double ke = 0;
  for (std::size_t i = 0; i < state.bodies.size(); ++i) ke += kinetic_energy_of(model.bodies[i], state.bodies[i]);
  return ke;
}

std::size_t World::contact_count() const {
  std::size_t n = 0;
  for (const Contact& c : state.contacts) n += in_contact(c);
  for (const Contact& c : state.wall_contacts) n += in_contact(c);
  return n;
}

std::size_t World::touching_pair_count() const {
  return grainlab::touching_pair_count(state.contacts) + grainlab::touching_pair_count(state.wall_contacts);
}

}  // namespace grainlab
