// World::step and its phases (see world.h for the recipe).
//
// Determinism: the broadphase emits pairs sorted by (a, b); each parallel loop
// writes only its own pair's, contact's or body's slot; the contacts are
// placed in pair order (a prefix sum over the pairs' counts) and forces are
// summed per body in a serial pass in contact order. So 1 and N threads give bit-identical states.
#include "dynamics/world.h"

#include "collision/dispatch.h"
#include "collision/narrowphase.h"
#include "collision/wall_bound.h"
#include "core/error.h"
#include "core/parallel.h"
#include "core/timer.h"
#include "dynamics/contact_lanes.h"
#include "dynamics/contact_law.h"
#include "dynamics/laws/registry.h"
#include "dynamics/integrator.h"
#include "dynamics/time_step.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

namespace grainlab {

namespace {

// Keeps the warm-start caches of pairs that survive from `old_pairs` into
// `pairs` (both sorted by key): a merge join, no hashing.
void carry_history(const std::vector<CandidatePair>& old_pairs, std::vector<CandidatePair>& pairs) {
  std::size_t j = 0;
  for (CandidatePair& p : pairs) {
    const auto k = p.key();
    while (j < old_pairs.size() && old_pairs[j].key() < k) ++j;
    if (j < old_pairs.size() && old_pairs[j].key() == k) p = old_pairs[j];
  }
}

// The piece-pair caches of pair pc of shapes a, b in `pool`, or null (none,
// or a block that does not fit: a state from elsewhere, collided cold).
PairCache* piece_block(std::vector<PairCache>& pool, const CandidatePair& pc, const PosedShape& a,
                       const PosedShape& b) {
  if (pc.pieces < 0) return nullptr;
  const auto first = static_cast<std::size_t>(pc.pieces);
  return first + static_cast<std::size_t>(piece_cache_count(a, b)) <= pool.size() ? &pool[first] : nullptr;
}

// Index of the first contact of pair (a, b) in `contacts` (sorted by (a, b,
// sub)), or where it would be: `hint` if it is that index, else by binary search.
std::size_t first_contact_of(const std::vector<Contact>& contacts, Index a, Index b, std::int32_t hint) {
  const auto of_pair = [&](std::size_t i) { return contacts[i].a == a && contacts[i].b == b; };
  if (hint >= 0 && static_cast<std::size_t>(hint) < contacts.size()) {
    const auto h = static_cast<std::size_t>(hint);
    if (of_pair(h) && (h == 0 || !of_pair(h - 1))) return h;
  }
  Contact key;
  key.a = a;
  key.b = b;
  key.sub = std::numeric_limits<std::int32_t>::min();
  return static_cast<std::size_t>(std::lower_bound(contacts.begin(), contacts.end(), key) - contacts.begin());
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
  return grainlab::critical_time_step(model, settings.expected_overlap_fraction).critical;
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
    if (!(dt > 0 && std::isfinite(dt))) input_error("time step {} s must be positive", dt);
    const TimeStepEstimate est = grainlab::critical_time_step(model, settings.expected_overlap_fraction);
    if (dt > est.critical) {
      const double ratio = dt / est.critical;
      input_error(
          "time step {:.3g} s is above the critical step {:.3g} s of this model (set by grain {} "
          "with contact stiffness {:.3g} N/m at an overlap of {:.2g} of its radius, damping ratio "
          "{:.2f}): the run would explode. Use a time step of at most {:.3g} s (about a tenth of the critical step is "
          "accurate), or scale the density by at least {:.3g} (numerics.density_scaling) for a "
          "quasi-static test",
          dt, est.critical, est.limiting_body, est.stiffness, settings.expected_overlap_fraction, est.damping_ratio,
          est.critical, ratio * ratio);
    }
    checked_dt_ = dt;
  }

  if (model.shapes.size() != shapes_classified_) classify_shapes();
  // The thread count: the settings' own, or the tuner's (core/thread_tuner.h).
  const bool tuned = settings.threads <= 0;
  if (tuned && tuner_.max_threads() != resolve_threads(0))
    tuner_ = ThreadTuner(resolve_threads(0), settings.thread_tuning);
  step_threads_ = tuned ? tuner_.threads() : settings.threads;
  const Stopwatch whole;
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
  if (tuned) tuner_.record(whole.seconds());
}

void World::classify_shapes() {
  const bool compounds = std::any_of(model.shapes.begin(), model.shapes.end(),
                                     [](const Shape& s) { return s.kind == ShapeKind::Compound; });
  sub_contact_slots_ = compounds ? kMaxSubContacts : 1;  // only compound routines write more than one
  spheres_only_ = std::all_of(model.shapes.begin(), model.shapes.end(),
                              [](const Shape& s) { return s.kind == ShapeKind::Sphere; });
  shapes_classified_ = model.shapes.size();
}

void World::compute_bounds() {
  const std::size_t n = state.bodies.size();
  const bool have_ref = state.x_at_rebuild.size() == n;
  const bool spheres = spheres_only();
  sphere_poses_.resize(spheres ? n : 0);
  const double max_sq = parallel_max(
      static_cast<std::ptrdiff_t>(n),
      [&](std::ptrdiff_t i) {
        rot_[i] = state.bodies[i].q.toRotationMatrix();
        if (spheres) sphere_poses_[i] = {state.bodies[i].x, model.bodies[i].radius};
        return have_ref ? (state.bodies[i].x - state.x_at_rebuild[i]).squaredNorm() : 0.0;
      },
      0.0, settings.serial_below, step_threads_);
  const double max_move_sq = have_ref ? max_sq : std::numeric_limits<double>::infinity();
  // Grain bounds (bounding sphere plus half the skin) only when the candidate
  // pairs are due for a rebuild: a grain has moved more than skin/2.
  rebuild_due_ = state.rebuild_pairs || max_move_sq > 0.25 * settings.skin * settings.skin;
  if (!rebuild_due_) return;
  for (std::size_t i = 0; i < n; ++i) {
    const double r = model.bodies[i].bounding_radius + 0.5 * settings.skin;
    aabb_[i] = {state.bodies[i].x.array() - r, state.bodies[i].x.array() + r};
  }
}

void World::broadphase() {
  const std::size_t n = state.bodies.size();
  // Grain-grain candidates: rebuilt from the bounds when they are due.
  if (rebuild_due_) {
    sap_.find_pairs(aabb_, candidates_);
    scratch_.resize(candidates_.size());
    for (std::size_t k = 0; k < candidates_.size(); ++k) {
      scratch_[k] = CandidatePair{};
      scratch_[k].a = candidates_[k].first;
      scratch_[k].b = candidates_[k].second;
      scratch_[k].cache.dir = (state.bodies[scratch_[k].b].x - state.bodies[scratch_[k].a].x);
    }
    carry_history(state.pairs, scratch_);
    state.pairs.swap(scratch_);
    if (sub_contact_slots() > 1) assign_piece_caches(state.pairs, false, state.piece_caches);  // compounds
    state.x_at_rebuild.resize(n);
    for (std::size_t i = 0; i < n; ++i) state.x_at_rebuild[i] = state.bodies[i].x;
    state.rebuild_pairs = false;
    ++profile.broadphase_rebuilds;
  }
  // Wall-grain candidates: few walls, found again every step (walls move),
  // but in a world of spheres, whose wall routines keep nothing in the
  // PairCache, they are kept while no wall has moved by skin/2 nor turned,
  // and found within a margin of 1.5 skins. That is exact: since they were
  // found, a grain has moved by at most a skin (skin/2 since the grain pairs'
  // rebuild, which finds these again, at most skin/2 before) and a wall by at
  // most skin/2, so a grain that may touch a wall now was within the margin.
  wall_rot_.resize(state.walls.size());
  for (std::size_t w = 0; w < state.walls.size(); ++w) wall_rot_[w] = state.walls[w].q.toRotationMatrix();
  const bool keep = spheres_only();
  if (keep && !wall_pairs_due()) return;
  const double margin = keep ? 1.5 * settings.skin : 0.0;
  scratch_.clear();
  for (std::size_t w = 0; w < model.walls.size(); ++w) {
    const WallBound bound = wall_bound(posed_wall(static_cast<Index>(w)));
    const Vec3& wx = state.walls[w].x;
    for (std::size_t i = 0; i < n; ++i) {
      const Vec3& x = state.bodies[i].x;
      if (!bound.may_touch(x, model.bodies[i].bounding_radius + margin)) continue;
      CandidatePair pc;
      pc.a = static_cast<Index>(w);
      pc.b = static_cast<Index>(i);
      // The GJK warm start of a faceted grain; a sphere's wall routines read
      // no cache, so theirs stays the default: then a kept list and one found
      // anew after a restore hold the same bits whenever each pair was found.
      if (!keep) pc.cache.dir = x - wx;
      scratch_.push_back(pc);
    }
  }
  carry_history(state.wall_pairs, scratch_);
  state.wall_pairs.swap(scratch_);
  if (sub_contact_slots() > 1) assign_piece_caches(state.wall_pairs, true, state.wall_piece_caches);
  state.wall_x_at_rebuild.clear();
  state.wall_q_at_rebuild.clear();
  if (!keep) return;
  for (const WallState& w : state.walls) {
    state.wall_x_at_rebuild.push_back(w.x);
    state.wall_q_at_rebuild.push_back(w.q);
  }
}

void World::assign_piece_caches(std::vector<CandidatePair>& pairs, bool walls, std::vector<PairCache>& pool) {
  piece_scratch_.clear();
  for (CandidatePair& p : pairs) {
    const int n = piece_cache_count(walls ? posed_wall(p.a) : posed_body(p.a), posed_body(p.b));
    const std::int32_t old = p.pieces;
    p.pieces = n > 0 ? static_cast<std::int32_t>(piece_scratch_.size()) : -1;
    if (n == 0) continue;
    if (old >= 0 && static_cast<std::size_t>(old) + n <= pool.size())
      piece_scratch_.insert(piece_scratch_.end(), pool.begin() + old, pool.begin() + old + n);
    else
      piece_scratch_.resize(piece_scratch_.size() + static_cast<std::size_t>(n));
  }
  pool.swap(piece_scratch_);
}

bool World::wall_pairs_due() const {
  if (rebuild_due_ || state.wall_x_at_rebuild.size() != state.walls.size()) return true;
  for (std::size_t w = 0; w < state.walls.size(); ++w) {
    if ((state.walls[w].x - state.wall_x_at_rebuild[w]).squaredNorm() > 0.25 * settings.skin * settings.skin)
      return true;
    if (state.walls[w].q.coeffs() != state.wall_q_at_rebuild[w].coeffs()) return true;
  }
  return false;
}

PosedShape World::posed_body(Index i) const {
  const BodyModel& m = model.bodies[i];
  const Shape& sh = model.shapes[m.shape];
  PosedShape p;
  p.kind = sh.kind;
  p.hull = &sh.hull;
  p.compound = &sh.compound;
  p.radius = m.radius;
  p.rot = &rot_[i];
  p.q = &state.bodies[i].q;
  p.pos = state.bodies[i].x;
  p.scale = m.scale;
  return p;
}

PosedShape World::posed_wall(Index w) const {
  const WallModel& wm = model.walls[w];
  PosedShape p;
  p.kind = wm.kind;
  p.half = wm.half;
  p.rot = &wall_rot_[w];
  p.q = &state.walls[w].q;
  p.pos = state.walls[w].x;
  return p;
}

int World::collide_pair(CandidatePair& pc, SubContact* out) {
  const BodyModel& ma = model.bodies[pc.a];
  const BodyModel& mb = model.bodies[pc.b];
  // Bounding spheres apart: no contact, no narrowphase.
  const double reach = ma.bounding_radius + mb.bounding_radius;
  if ((state.bodies[pc.b].x - state.bodies[pc.a].x).squaredNorm() > reach * reach) {
    pc.cache.warm = false;  // the last normal will be stale when they meet
    if (pc.pieces >= 0) {     // and so will the pieces'
      const PosedShape a = posed_body(pc.a), b = posed_body(pc.b);
      if (PairCache* pieces = piece_block(state.piece_caches, pc, a, b))
        for (int k = 0; k < piece_cache_count(a, b); ++k) pieces[k].warm = false;
    }
    return 0;
  }
  const PosedShape a = posed_body(pc.a), b = posed_body(pc.b);
  return collide_shapes(a, b, pc.cache, out, piece_block(state.piece_caches, pc, a, b));
}

inline ContactResult World::collide_spheres(const CandidatePair& pc) const {
  // collide_pair for two spheres, from their compact poses, without building
  // posed shapes or going through the shape-pair table: what
  // routines::sphere_sphere computes. A sphere pair's cache is never warm.
  const SpherePose& a = sphere_poses_[pc.a];
  const SpherePose& b = sphere_poses_[pc.b];
  const double reach = a.radius + b.radius;
  if ((b.x - a.x).squaredNorm() > reach * reach) return ContactResult{};
  return collide(SphereShape{a.x, a.radius}, SphereShape{b.x, b.radius});
}

int World::collide_wall(CandidatePair& pc, SubContact* out) {
  const PosedShape a = posed_wall(pc.a), b = posed_body(pc.b);
  return collide_shapes(a, b, pc.cache, out, piece_block(state.wall_piece_caches, pc, a, b));
}

void World::collide_list(std::vector<CandidatePair>& pairs, bool walls, std::vector<Contact>& contacts) {
  const std::size_t n = pairs.size();
  // Each pair collides into a per-thread buffer and copies its touching
  // results, in increasing sub-contact id, into its own fixed-capacity slot,
  // in parallel. Most pairs do not touch and write nothing but their count.
  // Slots per pair: one unless
  // a compound shape can touch in several places (only the compound routines
  // write more than one result), so a world of convex grains writes densely;
  // a pair of spheres is only counted here, its geometry made in the fill.
  const std::size_t slots = static_cast<std::size_t>(sub_contact_slots());
  if (sub_results_.size() < n * slots) sub_results_.resize(n * slots);
  sub_counts_.resize(n + 1);
  const bool spheres = spheres_only();
  parallel_for(
      static_cast<std::ptrdiff_t>(n),
      [&](std::ptrdiff_t k) {
        if (spheres && !walls) {  // only counted: the fill below computes the geometry again
          sub_counts_[k] = collide_spheres(pairs[k]).touching;
          return;
        }
        SubContact* out = &sub_results_[static_cast<std::size_t>(k) * slots];
        thread_local SubContact local[kMaxSubContacts];  // constructed once per thread, not per pair
        const int written = walls ? collide_wall(pairs[k], local) : collide_pair(pairs[k], local);
        int touching = 0;
        for (int r = 0; r < written; ++r) {
          if (!local[r].geo.touching) continue;
          assert(touching < static_cast<int>(slots));
          out[touching++] = local[r];
        }
        sub_counts_[k] = touching;
      },
      32, step_threads_, spheres ? settings.serial_below : 0);
  // Each pair's place in the new list: an exclusive prefix sum, so the list is
  // sorted by (a, b, sub) as the pairs are by (a, b), whatever the threads.
  std::size_t total = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const int c = sub_counts_[k];
    sub_counts_[k] = static_cast<int>(total);
    total += static_cast<std::size_t>(c);
  }
  sub_counts_[n] = static_cast<int>(total);
  // Fill in parallel; springs carried from last step's contact with the same
  // (a, b, sub), found in the sorted old list where the pair's hint says (if
  // it holds) or by binary search.
  std::vector<Contact>& next = next_contacts_[walls ? 1 : 0];
  next.resize(total);
  parallel_for(
      static_cast<std::ptrdiff_t>(n),
      [&](std::ptrdiff_t k) {
        CandidatePair& pair = pairs[k];
        const std::size_t begin = static_cast<std::size_t>(sub_counts_[k]);
        const std::size_t end = static_cast<std::size_t>(sub_counts_[k + 1]);
        const std::int32_t hint = pair.first_contact;
        pair.first_contact = begin == end ? CandidatePair::kNoContacts : static_cast<std::int32_t>(begin);
        if (begin == end) return;
        const SubContact* res = &sub_results_[static_cast<std::size_t>(k) * slots];
        std::size_t old = hint == CandidatePair::kNoContacts ? contacts.size()
                                                             : first_contact_of(contacts, pair.a, pair.b, hint);
        for (std::size_t i = begin; i < end; ++i) {
          Contact& c = next[i];  // written in place: every field is set
          c.a = pair.a;
          c.b = pair.b;
          if (spheres && !walls) {
            c.sub = 0;
            c.geo = collide_spheres(pair);
          } else {
            c.sub = res[i - begin].sub;
            c.geo = res[i - begin].geo;
          }
          while (old < contacts.size() && contacts[old] < c) ++old;
          const bool carried = old < contacts.size() && contacts[old].same_key(c);
          c.xi = carried ? contacts[old].xi : Vec3::Zero();
          c.force.setZero();  // forces() sets these three
          c.torque.setZero();
          c.normal_force = 0;
        }
      },
      64, step_threads_, spheres ? settings.serial_below : 0);
  contacts.swap(next);
}

void World::narrowphase() {
  collide_list(state.pairs, false, state.contacts);
  collide_list(state.wall_pairs, true, state.wall_contacts);
  profile.pair_tests += static_cast<std::int64_t>(state.pairs.size() + state.wall_pairs.size());
}

namespace {

// One contact's side of the law: its material pair, the velocity of b's
// material point minus a's at the contact point, the relative angular
// velocity, and the effective mass (kg) and radius (m).
struct ContactSides {
  const PairCoefficients* pair;
  Vec3 v_rel, w_rel;
  double m_eff, r_eff;
};

// Evaluates the contact law for contacts [first, first + kLanes) of `list`,
// four at a time (contact_lanes.h; the last block's missing lanes repeat its
// last contact and are dropped). sides(pc) gives a contact's ContactSides.
template <typename Law, typename Sides>
void evaluate_block(std::vector<Contact>& list, std::size_t first, double dt, const Sides& sides) {
  Contact* pcs[kLanes];
  Vec3 w_rel[kLanes];
  ContactLanes c;
  PairCoefficientsOf<Lanes> p;
  for (int l = 0; l < kLanes; ++l) {
    Contact& pc = list[std::min(first + static_cast<std::size_t>(l), list.size() - 1)];
    const ContactSides s = sides(pc);
    pcs[l] = &pc;
    w_rel[l] = s.w_rel;
    c.nx[l] = pc.geo.normal.x(), c.ny[l] = pc.geo.normal.y(), c.nz[l] = pc.geo.normal.z();
    c.delta[l] = pc.geo.depth;
    c.vx[l] = s.v_rel.x(), c.vy[l] = s.v_rel.y(), c.vz[l] = s.v_rel.z();
    c.m_eff[l] = s.m_eff, c.r_eff[l] = s.r_eff, c.gain[l] = pc.geo.gain;
    c.xix[l] = pc.xi.x(), c.xiy[l] = pc.xi.y(), c.xiz[l] = pc.xi.z();
    for (int i = 0; i < Law::pair_slots; ++i) p.c[i][l] = s.pair->c[i];
    p.friction[l] = s.pair->friction;
  }
  const ForceLanes f = contact_force_lanes<Law>(p, c, dt);
  for (int l = 0; l < kLanes && first + static_cast<std::size_t>(l) < list.size(); ++l) {
    Contact& pc = *pcs[l];
    pc.force = Vec3(f.fx[l], f.fy[l], f.fz[l]);
    pc.normal_force = f.f_n[l];
    pc.xi = Vec3(c.xix[l], c.xiy[l], c.xiz[l]);
    // The faceted contact's torque beyond the force at the point: twist times u'(D).
    pc.torque = patch_damping_torque(f.k.c_n[l], pc.geo.spread, pc.geo.normal, w_rel[l]) +
                (f.k.k_n[l] * pc.geo.depth) * pc.geo.twist;
  }
}

// The law over all of `list`, block by block, in parallel (blocks fixed by
// index, so the thread count changes nothing).
template <typename Law, typename Sides>
void evaluate_all(std::vector<Contact>& list, double dt, const Sides& sides, int threads,
                  std::ptrdiff_t serial_below) {
  parallel_for(
      static_cast<std::ptrdiff_t>((list.size() + kLanes - 1) / kLanes),
      [&](std::ptrdiff_t k) { evaluate_block<Law>(list, static_cast<std::size_t>(k) * kLanes, dt, sides); }, 32,
      threads, serial_below / kLanes);
}

}  // namespace

template <typename Law>
void World::forces_with(double dt) {
  // Per contact (all touching), four at a time, in parallel: the force on b at the contact point.
  const auto grain_sides = [&](const Contact& pc) {
    const BodyModel &ma = model.bodies[pc.a], &mb = model.bodies[pc.b];
    const BodyState &sa = state.bodies[pc.a], &sb = state.bodies[pc.b];
    const Vec3& p = pc.geo.point;
    return ContactSides{&pair(ma.material, mb.material),
                        (sb.v + sb.w.cross(p - sb.x)) - (sa.v + sa.w.cross(p - sa.x)), sb.w - sa.w,
                        ma.mass * mb.mass / (ma.mass + mb.mass), ma.radius * mb.radius / (ma.radius + mb.radius)};
  };
  evaluate_all<Law>(state.contacts, dt, grain_sides, step_threads_, settings.serial_below);

  // Walls: infinite mass and radius, translating at their prescribed velocity.
  const auto wall_sides = [&](const Contact& pc) {
    const BodyModel& mb = model.bodies[pc.b];
    const BodyState& sb = state.bodies[pc.b];
    const Vec3& p = pc.geo.point;
    return ContactSides{&pair(model.walls[pc.a].material, mb.material),
                        (sb.v + sb.w.cross(p - sb.x)) - state.walls[pc.a].v, sb.w, mb.mass, mb.radius};
  };
  evaluate_all<Law>(state.wall_contacts, dt, wall_sides, step_threads_, settings.serial_below);

  // Serial sums in contact order: independent of the thread count.
  const std::size_t n = state.bodies.size();
  const Vec3 g = gravity();
  for (std::size_t i = 0; i < n; ++i) {
    force_[i] = model.bodies[i].gravity_mass * g;
    torque_[i].setZero();
  }
  for (WallState& w : state.walls) w.force.setZero();
  for (const Contact& pc : state.contacts) {
    force_[pc.b] += pc.force;
    force_[pc.a] -= pc.force;
    torque_[pc.b] += (pc.geo.point - state.bodies[pc.b].x).cross(pc.force) + pc.torque;
    torque_[pc.a] -= (pc.geo.point - state.bodies[pc.a].x).cross(pc.force) + pc.torque;
  }
  for (const Contact& pc : state.wall_contacts) {
    force_[pc.b] += pc.force;
    torque_[pc.b] += (pc.geo.point - state.bodies[pc.b].x).cross(pc.force) + pc.torque;
    state.walls[pc.a].force -= pc.force;
  }
}

void World::forces(double dt) {
  // One force loop per registered law: the law is chosen once per step, and
  // its coefficients are inlined into the loop.
  with_law(model.law, [&]<typename Law>() { forces_with<Law>(dt); });
}

void World::integrate(double dt) {
  const std::size_t n = state.bodies.size();
  const auto body = [&](std::ptrdiff_t i) {
    BodyState& s = state.bodies[i];
    const BodyModel& m = model.bodies[i];
    s.v += (m.inv_mass * dt) * force_[i];
    s.x += dt * s.v;
    const bool isotropic = model.shapes[m.shape].isotropic;
    integrate_rotation(s.q, s.w, torque_[i], m.inertia, m.inv_inertia, dt, isotropic);
    motion_[i] = s.v.squaredNorm() + s.w.squaredNorm();
  };
  // A faceted grain's rotation (implicit midpoint, four quaternion updates)
  // costs some 280 ns, ten times a sphere's: 256 of them outweigh waking a
  // thread, so only a world of spheres keeps the serial threshold.
  parallel_for(static_cast<std::ptrdiff_t>(n), body, 256, step_threads_, spheres_only() ? settings.serial_below : 0);
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
