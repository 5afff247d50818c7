// The collision phases of World::step: bounds (rotations, the Verlet
// decision, the grains' boxes), broadphase (grain-grain candidate pairs by
// sweep and prune with their warm-start caches carried, wall-grain
// candidates) and narrowphase (each candidate through the shape-pair table,
// collision/dispatch.h, into the sorted contact lists with their springs
// carried). The driver owns the phases' scratch and what it found of the
// model's shapes; Model and State are handed to each phase.
//
// Determinism: the broadphase emits pairs sorted by (a, b); each parallel
// loop writes only its own pair's or contact's slot, and the contacts are
// placed in pair order (a prefix sum over the pairs' counts), so 1 and N
// threads give bit-identical contact lists.
#pragma once

#include "collision/aabb.h"
#include "collision/broadphase.h"
#include "collision/dispatch.h"
#include "collision/posed_shape.h"
#include "collision/sphere_pairs.h"
#include "dynamics/model.h"
#include "dynamics/profile.h"
#include "dynamics/state.h"
#include "dynamics/world_settings.h"

#include <cstddef>
#include <vector>

namespace grainlab {

// What a collision phase reads and writes in one step.
struct CollisionStep {
  const Model& model;
  State& state;
  const WorldSettings& settings;
  int threads = 1;
  StepProfile& profile;
};

class CollisionDriver {
 public:
  // Rotation matrices; whether the candidate pairs are due for a rebuild (a
  // grain moved more than skin/2), and then the grains' boxes.
  void bounds(const CollisionStep& s);
  // Grain-grain candidates (when due) and wall-grain candidates.
  void broadphase(const CollisionStep& s);
  // The touching contacts of every candidate pair, springs carried.
  void narrowphase(const CollisionStep& s);

  // A world of spheres stepped serially (compact(), one thread): the same
  // contacts, springs and bits as narrowphase(), but the grain-grain ones
  // made a few at a time, in pair order, as the forces phase asks for them
  // (contact_forces.h, GrainContactSource), so that each is made, pushed by
  // the law and summed while it is in cache, and every pair is tested once:
  //   narrowphase_walls(s);                        // the wall-grain contacts, whole
  //   auto& list = begin_compact_contacts();       // the new grain contacts, empty
  //   while (more_compact_contacts(s, k) > 0) ...  // up to k more appended to list
  //   end_compact_contacts(s);                     // list becomes State::contacts
  void narrowphase_walls(const CollisionStep& s);
  std::vector<Contact>& begin_compact_contacts();
  std::size_t more_compact_contacts(const CollisionStep& s, std::size_t want);
  void end_compact_contacts(const CollisionStep& s);

  // Body i / wall w as the narrowphase sees it, as of the last bounds /
  // broadphase phase.
  PosedShape posed_body(const Model& model, const State& state, Index i) const;
  PosedShape posed_wall(const Model& model, const State& state, Index w) const;
  // Every grain-grain pair takes the table's compact path (PairNeeds::compact),
  // as of the last bounds phase: the step's loops over bodies and pairs are
  // of cheap items and keep the serial threshold (WorldSettings::serial_below).
  bool compact() const { return compact_; }

 private:
  // What the pairs of the model's kinds need, asked of the shape-pair table
  // (collision/dispatch.h) whenever the count of shapes or walls changes (at
  // the start of each bounds phase): they are only ever added.
  void ask_table(const Model& model);
  bool wall_pairs_due(const CollisionStep& s) const;  // kept wall-grain candidates are out of date
  // Gives each pair that keeps extra caches (PairNeeds::extra_caches) its
  // block of them in `pool`: its own from the old pool if carried there
  // (carry_history), else cold ones; the old pool and `pool` swap.
  void assign_piece_caches(const CollisionStep& s, std::vector<CandidatePair>& pairs, bool walls,
                           std::vector<PairCache>& pool);
  // The geometry of compact pairs k to k + 3 (sphere_pairs.h; past the end
  // of `pairs`, the last pair again).
  void compact_group(const std::vector<CandidatePair>& pairs, std::size_t k, SpherePairsOut& geo) const;
  int collide_pair(const CollisionStep& s, CandidatePair& pc, SubContact* out);
  int collide_wall(const CollisionStep& s, CandidatePair& pc, SubContact* out);
  void collide_list(const CollisionStep& s, std::vector<CandidatePair>& pairs, bool walls,
                    std::vector<Contact>& contacts);

  std::size_t shapes_asked_ = 0, walls_asked_ = 0;  // model.shapes, model.walls as of ask_table()
  int sub_contact_slots_ = 1;    // most sub-contacts one pair may write
  bool extra_caches_ = false;    // some pair keeps extra caches
  bool compact_ = true;          // every grain-grain pair takes the compact path
  bool keep_wall_pairs_ = true;  // no wall-grain pair reads its cache: the list may be kept
  bool rebuild_due_ = true;  // bounds found the candidate pairs due for a rebuild
  SweepAndPrune sap_;
  std::vector<Mat3> rot_;
  // Where every pair is compact: each body's centre and radius side by side
  // (the narrowphase's only reads; a compact shape's radius, PosedShape's,
  // is its body's radius, and so is its bounding radius).
  std::vector<CompactPose> compact_poses_;
  std::vector<Mat3> wall_rot_;  // wall rotations, as of the last broadphase
  std::vector<Aabb> aabb_;
  std::vector<BodyPair> candidates_;
  std::vector<CandidatePair> scratch_;
  std::vector<PairCache> piece_scratch_;
  std::vector<SubContact> sub_results_;  // narrowphase: sub_contact_slots_ per pair
  std::vector<int> sub_counts_;          // narrowphase: touching results per pair, then offsets
  // The contact lists being compacted, grains' [0] and walls' [1]: one each,
  // so that neither is value-initialised anew every step after the other.
  std::vector<Contact> next_contacts_[2];
  // The compact pass's place: the next candidate pair, and the first of last
  // step's contacts not yet passed (both lists are sorted by (a, b)).
  std::size_t compact_pair_ = 0, compact_old_ = 0;
};

}  // namespace grainlab
