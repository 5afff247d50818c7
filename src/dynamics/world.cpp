// World::step and its phases (see world.h for the recipe).
//
// Determinism: the broadphase emits pairs sorted by (a, b); each parallel loop
// writes only its own pair's or body's slot; forces are summed per body in a
// serial pass in pair order. So 1 and N threads give bit-identical states.
#include "dynamics/world.h"

#include "collision/narrowphase.h"
#include "core/error.h"
#include "core/parallel.h"
#include "core/timer.h"
#include "dynamics/contact_law.h"
#include "dynamics/integrator.h"
#include "dynamics/time_step.h"

#include <algorithm>
#include <cmath>

namespace grainlab {

namespace {

// Keeps the history of pairs that survive from `old_pairs` into `pairs`
// (both sorted by key): a merge join, no hashing.
void carry_history(const std::vector<PairContact>& old_pairs, std::vector<PairContact>& pairs) {
  std::size_t j = 0;
  for (PairContact& p : pairs) {
    const auto k = p.key();
    while (j < old_pairs.size() && old_pairs[j].key() < k) ++j;
    if (j < old_pairs.size() && old_pairs[j].key() == k) p = old_pairs[j];
  }
}

}  // namespace

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
  return grainlab::critical_time_step(model, expected_overlap_fraction).critical;
}

void World::set_overrides(PhaseOverrides o) {
  overrides_ = std::move(o);
  if (prepared_) mix_pair_table();
}

void World::mix_pair_table() {
  // Only friction is overridden, and it mixes by the minimum (material.cpp
  // mix()): the Model's table with that one coefficient recomputed.
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
  rot_.resize(n);
  aabb_.resize(n);
  force_.assign(n, Vec3::Zero());
  torque_.assign(n, Vec3::Zero());
  kinetic_.assign(n, 0.0);
  if (skin <= 0) {
    double r_min = std::numeric_limits<double>::infinity();
    for (const BodyModel& b : model.bodies) r_min = std::min(r_min, b.radius);
    skin = std::isfinite(r_min) ? 0.2 * r_min : 1e-3;
  }
  // No forced rebuild: a restored State carries its own candidate pairs, and
  // added bodies make x_at_rebuild the wrong size, which forces one.
  checked_dt_ = -1;
  prepared_ = true;
}

void World::step(double dt) {
  if (!prepared_) prepare();
  if (dt != checked_dt_) {
    if (!(dt > 0 && std::isfinite(dt))) input_error("time step {} s must be positive", dt);
    const TimeStepEstimate est = grainlab::critical_time_step(model, expected_overlap_fraction);
    if (dt > est.critical) {
      const double ratio = dt / est.critical;
      input_error(
          "time step {:.3g} s is above the critical step {:.3g} s of this model (set by grain {} "
          "with contact stiffness {:.3g} N/m at an overlap of {:.2g} of its radius): the run would "
          "explode. Use a time step of at most {:.3g} s (about a tenth of the critical step is "
          "accurate), or scale the density by at least {:.3g} (numerics.density_scaling) for a "
          "quasi-static test",
          dt, est.critical, est.limiting_body, est.stiffness, expected_overlap_fraction,
          est.critical, ratio * ratio);
    }
    checked_dt_ = dt;
  }

  Stopwatch sw;
  const auto lap = [&](Phase p) {
    profile[p] += sw.seconds();
    sw.reset();
  };
  compute_bounds();
  lap(Phase::Bounds);
  broadphase();
  lap(Phase::Broadphase);
  narrowphase();
  lap(Phase::Narrowphase);
  forces(dt);
  lap(Phase::Forces);
  for (auto& c : controllers_) c(*this, dt);
  lap(Phase::Controllers);
  integrate(dt);
  lap(Phase::Integrate);
  state.time += dt;
  ++state.step;
  bookkeeping();
  lap(Phase::Bookkeeping);
  ++profile.steps;
}

void World::compute_bounds() {
  const std::size_t n = state.bodies.size();
  double max_sq = 0;
  const bool have_ref = state.x_at_rebuild.size() == n;
#pragma omp parallel for schedule(static) reduction(max : max_sq) if (n > 256)
  for (std::size_t i = 0; i < n; ++i) {
    rot_[i] = state.bodies[i].q.toRotationMatrix();
    if (have_ref) max_sq = std::max(max_sq, (state.bodies[i].x - state.x_at_rebuild[i]).squaredNorm());
  }
  max_move_sq_ = have_ref ? max_sq : std::numeric_limits<double>::infinity();
}

void World::broadphase() {
  const std::size_t n = state.bodies.size();
  // Grain-grain candidates: rebuilt only when a grain has moved more than skin/2.
  if (state.rebuild_pairs || max_move_sq_ > 0.25 * skin * skin) {
    for (std::size_t i = 0; i < n; ++i) {
      const double r = model.bodies[i].bounding_radius + 0.5 * skin;
      aabb_[i] = {state.bodies[i].x.array() - r, state.bodies[i].x.array() + r};
    }
    sap_.find_pairs(aabb_, candidates_);
    scratch_.resize(candidates_.size());
    for (std::size_t k = 0; k < candidates_.size(); ++k) {
      scratch_[k] = PairContact{};
      scratch_[k].a = candidates_[k].first;
      scratch_[k].b = candidates_[k].second;
      scratch_[k].dir = (state.bodies[scratch_[k].b].x - state.bodies[scratch_[k].a].x);
    }
    carry_history(state.pairs, scratch_);
    state.pairs.swap(scratch_);
    state.x_at_rebuild.resize(n);
    for (std::size_t i = 0; i < n; ++i) state.x_at_rebuild[i] = state.bodies[i].x;
    state.rebuild_pairs = false;
    ++profile.broadphase_rebuilds;
  }
  // Wall-grain candidates: few walls, rebuilt every step (walls move).
  scratch_.clear();
  for (std::size_t w = 0; w < model.walls.size(); ++w) {
    const WallState& ws = state.walls[w];
    const WallModel& wm = model.walls[w];
    const Vec3 normal = ws.q * Vec3::UnitZ();
    Aabb box;
    if (wm.kind == WallModel::Kind::Box) {
      const Vec3 ext = ws.q.toRotationMatrix().cwiseAbs() * wm.half;
      box = {ws.x - ext, ws.x + ext};
    }
    for (std::size_t i = 0; i < n; ++i) {
      const Vec3& x = state.bodies[i].x;
      const double r = model.bodies[i].bounding_radius;
      const bool near = wm.kind == WallModel::Kind::Plane
                            ? normal.dot(x - ws.x) < r
                            : box.overlaps(Aabb{x.array() - r, x.array() + r});
      if (!near) continue;
      PairContact pc;
      pc.a = static_cast<Index>(w);
      pc.b = static_cast<Index>(i);
      pc.dir = x - ws.x;
      scratch_.push_back(pc);
    }
  }
  carry_history(state.wall_pairs, scratch_);
  state.wall_pairs.swap(scratch_);
}

ContactResult World::collide_pair(PairContact& pc) const {
  const BodyModel& ma = model.bodies[pc.a];
  const BodyModel& mb = model.bodies[pc.b];
  const BodyState& sa = state.bodies[pc.a];
  const BodyState& sb = state.bodies[pc.b];
  // Bounding spheres apart: no contact, no GJK.
  const double reach = ma.bounding_radius + mb.bounding_radius;
  if ((sb.x - sa.x).squaredNorm() > reach * reach) {
    pc.warm = false;  // the last normal will be stale when they meet
    return {};
  }
  const Shape& sha = model.shapes[ma.shape];
  const Shape& shb = model.shapes[mb.shape];
  const bool poly_a = sha.kind == Shape::Kind::Polytope, poly_b = shb.kind == Shape::Kind::Polytope;
  if (!poly_a && !poly_b)
    return collide(SphereShape{sa.x, ma.radius}, SphereShape{sb.x, mb.radius});
  if (poly_a && poly_b) {
    PolytopeShape a{&sha.hull, rot_[pc.a], sa.x, ma.scale, pc.hint_a};
    PolytopeShape b{&shb.hull, rot_[pc.b], sb.x, mb.scale, pc.hint_b};
    ContactResult r = collide_convex(a, b, pc.dir, pc.warm);
    pc.hint_a = a.hint;
    pc.hint_b = b.hint;
    pc.warm = true;
    return r;
  }
  if (poly_b) {  // sphere a, polytope b
    PolytopeShape b{&shb.hull, rot_[pc.b], sb.x, mb.scale, pc.hint_b};
    ContactResult r = collide_convex(SphereShape{sa.x, ma.radius}, b, pc.dir);
    pc.hint_b = b.hint;
    return r;
  }
  // polytope a, sphere b: collide (b, a) and flip the normal.
  PolytopeShape a{&sha.hull, rot_[pc.a], sa.x, ma.scale, pc.hint_a};
  Vec3 flipped = -pc.dir;
  ContactResult r = collide_convex(SphereShape{sb.x, mb.radius}, a, flipped);
  pc.dir = -flipped;
  pc.hint_a = a.hint;
  r.normal = -r.normal;
  return r;
}

ContactResult World::collide_wall(PairContact& pc) const {
  const WallModel& wm = model.walls[pc.a];
  const WallState& ws = state.walls[pc.a];
  const BodyModel& mb = model.bodies[pc.b];
  const BodyState& sb = state.bodies[pc.b];
  const Shape& shb = model.shapes[mb.shape];
  const bool poly = shb.kind == Shape::Kind::Polytope;
  if (wm.kind == WallModel::Kind::Plane) {
    const PlaneShape plane{ws.x, ws.q * Vec3::UnitZ()};
    if (!poly) return collide(plane, SphereShape{sb.x, mb.radius});
    PolytopeShape b{&shb.hull, rot_[pc.b], sb.x, mb.scale, pc.hint_b};
    ContactResult r = collide(plane, b);
    pc.hint_b = b.hint;
    return r;
  }
  const BoxShape box{ws.q.toRotationMatrix(), ws.x, wm.half};
  if (!poly) return collide_convex(box, SphereShape{sb.x, mb.radius}, pc.dir);
  PolytopeShape b{&shb.hull, rot_[pc.b], sb.x, mb.scale, pc.hint_b};
  ContactResult r = collide_convex(box, b, pc.dir, pc.warm);
  pc.hint_b = b.hint;
  pc.warm = true;
  return r;
}

void World::narrowphase() {
  auto& pairs = state.pairs;
  parallel_for(static_cast<std::ptrdiff_t>(pairs.size()),
               [&](std::ptrdiff_t k) { pairs[k].geo = collide_pair(pairs[k]); }, 32);
  auto& wp = state.wall_pairs;
  parallel_for(static_cast<std::ptrdiff_t>(wp.size()),
               [&](std::ptrdiff_t k) { wp[k].geo = collide_wall(wp[k]); }, 32);
  profile.pair_tests += static_cast<std::int64_t>(pairs.size() + wp.size());
}

namespace {

// Evaluates the contact law for one pair whose sides move with relative
// velocity v_rel at the contact point and relative angular velocity w_rel.
template <typename Law>
void evaluate(PairContact& pc, const PairCoefficients& coeffs, const Vec3& v_rel, const Vec3& w_rel,
              double m_eff, double r_eff, double dt) {
  const ContactKinematics c{pc.geo.normal, pc.geo.depth, v_rel, m_eff, r_eff};
  LawCoefficients law;
  pc.force = contact_force<Law>(coeffs, c, dt, pc.xi, &pc.normal_force, &law);
  pc.torque = patch_damping_torque(law.c_n, pc.geo.spread, c.normal, w_rel);
}

// A pair that is not touching carries no force and forgets its spring.
void release(PairContact& pc) {
  pc.xi.setZero();
  pc.force.setZero();
  pc.torque.setZero();
  pc.normal_force = 0;
}

}  // namespace

template <typename Law>
void World::forces_with(double dt) {
  // Per pair, in parallel: the force on b at the contact point.
  const auto grain_pair = [&](std::ptrdiff_t k) {
    PairContact& pc = state.pairs[k];
    if (!pc.geo.touching) return release(pc);
    const BodyModel &ma = model.bodies[pc.a], &mb = model.bodies[pc.b];
    const BodyState &sa = state.bodies[pc.a], &sb = state.bodies[pc.b];
    const Vec3& p = pc.geo.point;
    evaluate<Law>(pc, pair(ma.material, mb.material),
                  (sb.v + sb.w.cross(p - sb.x)) - (sa.v + sa.w.cross(p - sa.x)), sb.w - sa.w,
                  ma.mass * mb.mass / (ma.mass + mb.mass), ma.radius * mb.radius / (ma.radius + mb.radius), dt);
  };
  parallel_for(static_cast<std::ptrdiff_t>(state.pairs.size()), grain_pair, 128);

  // Walls: infinite mass and radius, translating at their prescribed velocity.
  const auto wall_pair = [&](std::ptrdiff_t k) {
    PairContact& pc = state.wall_pairs[k];
    if (!pc.geo.touching) return release(pc);
    const BodyModel& mb = model.bodies[pc.b];
    const BodyState& sb = state.bodies[pc.b];
    const Vec3& p = pc.geo.point;
    evaluate<Law>(pc, pair(model.walls[pc.a].material, mb.material),
                  (sb.v + sb.w.cross(p - sb.x)) - state.walls[pc.a].v, sb.w, mb.mass, mb.radius, dt);
  };
  parallel_for(static_cast<std::ptrdiff_t>(state.wall_pairs.size()), wall_pair, 128);

  // Serial sums in pair order: independent of the thread count.
  const std::size_t n = state.bodies.size();
  const Vec3 g = gravity();
  for (std::size_t i = 0; i < n; ++i) {
    force_[i] = model.bodies[i].gravity_mass * g;
    torque_[i].setZero();
  }
  for (WallState& w : state.walls) w.force.setZero();
  for (const PairContact& pc : state.pairs) {
    if (!pc.geo.touching) continue;
    force_[pc.b] += pc.force;
    force_[pc.a] -= pc.force;
    torque_[pc.b] += (pc.geo.point - state.bodies[pc.b].x).cross(pc.force) + pc.torque;
    torque_[pc.a] -= (pc.geo.point - state.bodies[pc.a].x).cross(pc.force) + pc.torque;
  }
  for (const PairContact& pc : state.wall_pairs) {
    if (!pc.geo.touching) continue;
    force_[pc.b] += pc.force;
    torque_[pc.b] += (pc.geo.point - state.bodies[pc.b].x).cross(pc.force) + pc.torque;
    state.walls[pc.a].force -= pc.force;
  }
}

void World::forces(double dt) {
  switch (model.law) {
    case ContactLaw::Hooke: forces_with<HookeLaw>(dt); break;
    case ContactLaw::HertzUser: forces_with<HertzUserLaw>(dt); break;
    case ContactLaw::HertzMaterial: forces_with<HertzMaterialLaw>(dt); break;
  }
}

void World::integrate(double dt) {
  const std::size_t n = state.bodies.size();
  const auto body = [&](std::ptrdiff_t i) {
    BodyState& s = state.bodies[i];
    const BodyModel& m = model.bodies[i];
    s.v += (m.inv_mass * dt) * force_[i];
    s.x += dt * s.v;
    const bool isotropic = model.shapes[m.shape].kind == Shape::Kind::Sphere;
    integrate_rotation(s.q, s.w, torque_[i], m.inertia, m.inv_inertia, dt, isotropic);
    kinetic_[i] = kinetic_energy_of(m, s);
  };
  parallel_for(static_cast<std::ptrdiff_t>(n), body, 256);
  for (WallState& w : state.walls) w.x += dt * w.v;
}

void World::bookkeeping() {
  double ke = 0;
  for (double k : kinetic_) ke += k;
  std::size_t touching = 0;
  for (const PairContact& pc : state.pairs) touching += in_contact(pc);
  for (const PairContact& pc : state.wall_pairs) touching += in_contact(pc);
  profile.contacts += static_cast<std::int64_t>(touching);
  if (!std::isfinite(ke)) {
    for (std::size_t i = 0; i < state.bodies.size(); ++i) {
      if (!state.bodies[i].x.allFinite() || !state.bodies[i].v.allFinite())
        throw RunError(fmt::format(
            "step {} (t = {:.6g} s): grain {} has a non-finite position or velocity; the run went "
            "unstable. Reduce the time step or check the contact stiffness",
            state.step, state.time, i));
    }
    throw RunError(fmt::format("step {}: kinetic energy is not finite; the run went unstable", state.step));
  }
}

double World::kinetic_energy() const {
  double ke = 0;
  for (std::size_t i = 0; i < state.bodies.size(); ++i) ke += kinetic_energy_of(model.bodies[i], state.bodies[i]);
  return ke;
}

std::size_t World::contact_count() const {
  std::size_t n = 0;
  for (const PairContact& pc : state.pairs) n += in_contact(pc);
  for (const PairContact& pc : state.wall_pairs) n += in_contact(pc);
  return n;
}

}  // namespace grainlab
