// The collision phases of World::step (see collision_driver.h).
#include "dynamics/collision_driver.h"

#include "collision/dispatch.h"
#include "collision/narrowphase.h"
#include "collision/sphere_pairs.h"
#include "collision/wall_bound.h"
#include "core/parallel.h"

#include <algorithm>
#include <array>
#include <cassert>
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

void CollisionDriver::ask_table(const Model& model) {
  std::array<bool, kMaxShapeKinds> grain{}, wall{};  // the kinds the model has
  for (const Shape& sh : model.shapes) grain[static_cast<int>(sh.kind)] = true;
  for (const WallModel& w : model.walls) wall[static_cast<int>(w.kind)] = true;
  sub_contact_slots_ = 1, extra_caches_ = false, compact_ = true, keep_wall_pairs_ = true;
  const auto meet = [&](int a, int b, bool walls) {
    const PairNeeds& needs = pair_needs(static_cast<ShapeKind>(a), static_cast<ShapeKind>(b));
    sub_contact_slots_ = std::max(sub_contact_slots_, needs.sub_contacts);
    extra_caches_ = extra_caches_ || needs.extra_caches;
    if (walls)
      keep_wall_pairs_ = keep_wall_pairs_ && !needs.reads_cache;
    else
      compact_ = compact_ && needs.compact;
  };
  for (int b = 0; b < kMaxShapeKinds; ++b) {
    if (!grain[b]) continue;
    for (int a = 0; a <= b; ++a)
      if (grain[a]) meet(a, b, false);
    for (int w = 0; w < kMaxShapeKinds; ++w)
      if (wall[w]) meet(w, b, true);
  }
  shapes_asked_ = model.shapes.size();
  walls_asked_ = model.walls.size();
}

void CollisionDriver::bounds(const CollisionStep& s) {
  if (s.model.shapes.size() != shapes_asked_ || s.model.walls.size() != walls_asked_) ask_table(s.model);
  const std::size_t n = s.state.bodies.size();
  rot_.resize(n);
  aabb_.resize(n);
  const bool have_ref = s.state.x_at_rebuild.size() == n;
  const bool compact = compact_;
  compact_poses_.resize(compact ? n : 0);
  const double max_sq = parallel_max(
      static_cast<std::ptrdiff_t>(n),
      [&](std::ptrdiff_t i) {
        rot_[i] = s.state.bodies[i].q.toRotationMatrix();
        if (compact) compact_poses_[i] = {s.state.bodies[i].x, s.model.bodies[i].radius};
        return have_ref ? (s.state.bodies[i].x - s.state.x_at_rebuild[i]).squaredNorm() : 0.0;
      },
      0.0, s.settings.serial_below, s.threads);
  const double max_move_sq = have_ref ? max_sq : std::numeric_limits<double>::infinity();
  // Grain bounds (bounding sphere plus half the skin) only when the candidate
  // pairs are due for a rebuild: a grain has moved more than skin/2.
  rebuild_due_ = s.state.rebuild_pairs || max_move_sq > 0.25 * s.settings.skin * s.settings.skin;
  if (!rebuild_due_) return;
  for (std::size_t i = 0; i < n; ++i) {
    const double r = s.model.bodies[i].bounding_radius + 0.5 * s.settings.skin;
    aabb_[i] = {s.state.bodies[i].x.array() - r, s.state.bodies[i].x.array() + r};
  }
}

void CollisionDriver::broadphase(const CollisionStep& s) {
  const std::size_t n = s.state.bodies.size();
  // Grain-grain candidates: rebuilt from the bounds when they are due.
  if (rebuild_due_) {
    sap_.find_pairs(aabb_, candidates_);
    scratch_.resize(candidates_.size());
    for (std::size_t k = 0; k < candidates_.size(); ++k) {
      scratch_[k] = CandidatePair{};
      scratch_[k].a = candidates_[k].first;
      scratch_[k].b = candidates_[k].second;
      scratch_[k].cache.dir = (s.state.bodies[scratch_[k].b].x - s.state.bodies[scratch_[k].a].x);
    }
    carry_history(s.state.pairs, scratch_);
    s.state.pairs.swap(scratch_);
    if (extra_caches_) assign_piece_caches(s, s.state.pairs, false, s.state.piece_caches);
    s.state.x_at_rebuild.resize(n);
    for (std::size_t i = 0; i < n; ++i) s.state.x_at_rebuild[i] = s.state.bodies[i].x;
    s.state.rebuild_pairs = false;
    ++s.profile.broadphase_rebuilds;
  }
  // Wall-grain candidates: few walls, found again every step (walls move),
  // but where no wall pair's routine reads its PairCache (PairNeeds; a world
  // of spheres), they are kept while no wall has moved by skin/2 nor turned,
  // and found within a margin of 1.5 skins. That is exact: since they were
  // found, a grain has moved by at most a skin (skin/2 since the grain pairs'
  // rebuild, which finds these again, at most skin/2 before) and a wall by at
  // most skin/2, so a grain that may touch a wall now was within the margin.
  wall_rot_.resize(s.state.walls.size());
  for (std::size_t w = 0; w < s.state.walls.size(); ++w) wall_rot_[w] = s.state.walls[w].q.toRotationMatrix();
  const bool keep = keep_wall_pairs_;
  if (keep && !wall_pairs_due(s)) return;
  const double margin = keep ? 1.5 * s.settings.skin : 0.0;
  scratch_.clear();
  for (std::size_t w = 0; w < s.model.walls.size(); ++w) {
    const WallBound bound = wall_bound(posed_wall(s.model, s.state, static_cast<Index>(w)));
    const Vec3& wx = s.state.walls[w].x;
    for (std::size_t i = 0; i < n; ++i) {
      const Vec3& x = s.state.bodies[i].x;
      if (!bound.may_touch(x, s.model.bodies[i].bounding_radius + margin)) continue;
      CandidatePair pc;
      pc.a = static_cast<Index>(w);
      pc.b = static_cast<Index>(i);
      // The GJK warm start of a faceted grain; where no routine reads the
      // cache, it stays the default: then a kept list and one found anew
      // after a restore hold the same bits whenever each pair was found.
      if (!keep) pc.cache.dir = x - wx;
      scratch_.push_back(pc);
    }
  }
  carry_history(s.state.wall_pairs, scratch_);
  s.state.wall_pairs.swap(scratch_);
  if (extra_caches_) assign_piece_caches(s, s.state.wall_pairs, true, s.state.wall_piece_caches);
  s.state.wall_x_at_rebuild.clear();
  s.state.wall_q_at_rebuild.clear();
  if (!keep) return;
  for (const WallState& w : s.state.walls) {
    s.state.wall_x_at_rebuild.push_back(w.x);
    s.state.wall_q_at_rebuild.push_back(w.q);
  }
}

void CollisionDriver::assign_piece_caches(const CollisionStep& s, std::vector<CandidatePair>& pairs, bool walls,
                                          std::vector<PairCache>& pool) {
  piece_scratch_.clear();
  for (CandidatePair& p : pairs) {
    const PosedShape a = walls ? posed_wall(s.model, s.state, p.a) : posed_body(s.model, s.state, p.a);
    const int n = piece_cache_count(a, posed_body(s.model, s.state, p.b));
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

bool CollisionDriver::wall_pairs_due(const CollisionStep& s) const {
  if (rebuild_due_ || s.state.wall_x_at_rebuild.size() != s.state.walls.size()) return true;
  for (std::size_t w = 0; w < s.state.walls.size(); ++w) {
    if ((s.state.walls[w].x - s.state.wall_x_at_rebuild[w]).squaredNorm() > 0.25 * s.settings.skin * s.settings.skin)
      return true;
    if (s.state.walls[w].q.coeffs() != s.state.wall_q_at_rebuild[w].coeffs()) return true;
  }
  return false;
}

PosedShape CollisionDriver::posed_body(const Model& model, const State& state, Index i) const {
  const BodyModel& m = model.bodies[i];
  const Shape& sh = model.shapes[m.shape];
  PosedShape p;
  p.kind = sh.kind;
  p.geometry = sh.geometry.get();
  p.radius = m.radius;
  p.rot = &rot_[i];
  p.q = &state.bodies[i].q;
  p.pos = state.bodies[i].x;
  p.scale = m.scale;
  return p;
}

PosedShape CollisionDriver::posed_wall(const Model& model, const State& state, Index w) const {
  const WallModel& wm = model.walls[w];
  PosedShape p;
  p.kind = wm.kind;
  p.geometry = &wm.half;  // a box's; a plane reads none
  p.rot = &wall_rot_[w];
  p.q = &state.walls[w].q;
  p.pos = state.walls[w].x;
  return p;
}

int CollisionDriver::collide_pair(const CollisionStep& s, CandidatePair& pc, SubContact* out) {
  const BodyModel& ma = s.model.bodies[pc.a];
  const BodyModel& mb = s.model.bodies[pc.b];
  // Bounding spheres apart: no contact, no narrowphase.
  const double reach = ma.bounding_radius + mb.bounding_radius;
  if ((s.state.bodies[pc.b].x - s.state.bodies[pc.a].x).squaredNorm() > reach * reach) {
    pc.cache.warm = false;  // the last normal will be stale when they meet
    if (pc.pieces >= 0 && !pc.pieces_cold) {  // and so will the pieces' (once made cold, they stay so)
      const PosedShape a = posed_body(s.model, s.state, pc.a), b = posed_body(s.model, s.state, pc.b);
      if (PairCache* pieces = piece_block(s.state.piece_caches, pc, a, b))
        for (int k = 0; k < piece_cache_count(a, b); ++k) pieces[k].warm = false;
      pc.pieces_cold = true;
    }
    return 0;
  }
  pc.pieces_cold = false;
  const PosedShape a = posed_body(s.model, s.state, pc.a), b = posed_body(s.model, s.state, pc.b);
  return collide_shapes(a, b, pc.cache, out, piece_block(s.state.piece_caches, pc, a, b));
}

int CollisionDriver::collide_wall(const CollisionStep& s, CandidatePair& pc, SubContact* out) {
  const PosedShape a = posed_wall(s.model, s.state, pc.a), b = posed_body(s.model, s.state, pc.b);
  return collide_shapes(a, b, pc.cache, out, piece_block(s.state.wall_piece_caches, pc, a, b));
}

void CollisionDriver::collide_list(const CollisionStep& s, std::vector<CandidatePair>& pairs, bool walls,
                                   std::vector<Contact>& contacts) {
  const std::size_t n = pairs.size();
  // Each pair collides into a per-thread buffer and copies its touching
  // results, in increasing sub-contact id, into its own fixed-capacity slot,
  // in parallel. Most pairs do not touch and write nothing but their count.
  // Slots per pair: the most any pair of the model's kinds writes
  // (PairNeeds::sub_contacts: one unless a compound shape can touch in
  // several places), so a world of convex grains writes densely; a compact
  // pair is only counted here, its geometry made in the fill.
  const std::size_t slots = static_cast<std::size_t>(sub_contact_slots_);
  if (sub_results_.size() < n * slots) sub_results_.resize(n * slots);
  sub_counts_.resize(n + 1);
  const bool compact = compact_ && !walls;
  if (compact)  // only counted, four pairs at a time: the fill below computes the geometry again
    parallel_for(
        static_cast<std::ptrdiff_t>((n + 3) / 4),
        [&](std::ptrdiff_t g) {
          const std::size_t k = 4 * static_cast<std::size_t>(g);
          SpherePairsOut geo;
          compact_group(pairs, k, geo);
          for (std::size_t l = 0; l < 4 && k + l < n; ++l) sub_counts_[k + l] = geo.depth[l] > 0;
        },
        8, s.threads, s.settings.serial_below / 4);
  else
    parallel_for(
      static_cast<std::ptrdiff_t>(n),
      [&](std::ptrdiff_t k) {
        SubContact* out = &sub_results_[static_cast<std::size_t>(k) * slots];
        thread_local SubContact local[kMaxSubContacts];  // constructed once per thread, not per pair
        const int written = walls ? collide_wall(s, pairs[k], local) : collide_pair(s, pairs[k], local);
        int touching = 0;
        for (int r = 0; r < written; ++r) {
          if (!local[r].geo.touching) continue;
          assert(touching < static_cast<int>(slots));
          out[touching++] = local[r];
        }
        sub_counts_[k] = touching;
      },
      32, s.threads, compact_ ? s.settings.serial_below : 0);
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
          if (compact) {
            c.sub = 0;
            c.geo = collide_compact(compact_poses_[pair.a], compact_poses_[pair.b]);
          } else {
            c.sub = res[i - begin].sub;
            c.geo = res[i - begin].geo;
          }
          while (old < contacts.size() && contacts[old] < c) ++old;
          const bool carried = old < contacts.size() && contacts[old].same_key(c);
          c.xi = carried ? contacts[old].xi : Vec3::Zero();
          c.force.setZero();  // the forces phase sets these three
          c.torque.setZero();
          c.normal_force = 0;
        }
      },
      64, s.threads, compact_ ? s.settings.serial_below : 0);
  contacts.swap(next);
}

void CollisionDriver::narrowphase(const CollisionStep& s) {
  collide_list(s, s.state.pairs, false, s.state.contacts);
  narrowphase_walls(s);
  s.profile.pair_tests += static_cast<std::int64_t>(s.state.pairs.size());
}

void CollisionDriver::narrowphase_walls(const CollisionStep& s) {
  collide_list(s, s.state.wall_pairs, true, s.state.wall_contacts);
  s.profile.pair_tests += static_cast<std::int64_t>(s.state.wall_pairs.size());
}

std::vector<Contact>& CollisionDriver::begin_compact_contacts() {
  assert(compact_);
  compact_pair_ = compact_old_ = 0;
  next_contacts_[0].clear();  // keeps its capacity: no allocation after the first steps
  return next_contacts_[0];
}

void CollisionDriver::compact_group(const std::vector<CandidatePair>& pairs, std::size_t k,
                                    SpherePairsOut& geo) const {
  SphereXYZR a[4], b[4];
  for (std::size_t l = 0; l < 4; ++l) {
    const CandidatePair& pair = pairs[std::min(k + l, pairs.size() - 1)];
    a[l] = compact_poses_[pair.a].x.data();  // x, y, z, radius side by side
    b[l] = compact_poses_[pair.b].x.data();
  }
  sphere_pairs(a, b, geo);
}

std::size_t CollisionDriver::more_compact_contacts(const CollisionStep& s, std::size_t want) {
  std::vector<CandidatePair>& pairs = s.state.pairs;
  const std::vector<Contact>& old = s.state.contacts;
  std::vector<Contact>& next = next_contacts_[0];
  const std::size_t n = pairs.size(), first = next.size();
  std::size_t k = compact_pair_, o = compact_old_;
  for (; k < n && next.size() - first < want; k += 4) {
    SpherePairsOut geo;
    compact_group(pairs, k, geo);
    for (int l = 0; l < 4 && k + static_cast<std::size_t>(l) < n; ++l) {
      CandidatePair& pair = pairs[k + static_cast<std::size_t>(l)];
      if (!(geo.depth[l] > 0)) {
        pair.first_contact = CandidatePair::kNoContacts;
        continue;
      }
      pair.first_contact = static_cast<std::int32_t>(next.size());
      Contact c;
      c.a = pair.a;
      c.b = pair.b;
      c.sub = 0;
      c.geo = sphere_pair_result(geo, l);
      // The spring carried from last step's contact of the pair (the pairs and
      // both lists ascend, so one cursor finds it).
      while (o < old.size() && old[o] < c) ++o;
      if (o < old.size() && old[o].same_key(c)) c.xi = old[o].xi;
      next.push_back(c);
    }
  }
  compact_pair_ = std::min(k, n), compact_old_ = o;
  return next.size() - first;
}

void CollisionDriver::end_compact_contacts(const CollisionStep& s) {
  assert(compact_pair_ == s.state.pairs.size());
  s.state.contacts.swap(next_contacts_[0]);
  s.profile.pair_tests += static_cast<std::int64_t>(s.state.pairs.size());
}

}  // namespace grainlab
