// The changing part of a simulation (MuJoCo's mjData): poses, velocities,
// wall motion and the contact history. Saving a State (with its Model) is a
// full checkpoint; restoring it reproduces the run bit for bit.
#pragma once

#include "collision/contact_result.h"
#include "core/types.h"

#include <cstdint>
#include <vector>

namespace grainlab {

// Hot per-body state, packed.
struct BodyState {
  Vec3 x = Vec3::Zero();  // centre of mass (m)
  Vec3 v = Vec3::Zero();  // velocity (m/s)
  Vec3 w = Vec3::Zero();  // angular velocity, world frame (rad/s)
  Quat q = Quat::Identity();  // orientation: local (principal) frame to world
};

struct WallState {
  Vec3 x = Vec3::Zero();  // plane: a point on it; box: its centre (m)
  Quat q = Quat::Identity();  // plane: local +z is the outward normal
  Vec3 v = Vec3::Zero();      // prescribed translational velocity (m/s)
  Vec3 force = Vec3::Zero();  // force the grains put on the wall in the last step (N)
};

// One pair of a grain with a grain (a < b) or a wall with a grain (a = wall).
// The pair lives while the broadphase keeps it; its history goes with it.
struct PairContact {
  Index a = 0, b = 0;
  Vec3 dir = Vec3::UnitX();  // warm start for GJK: last normal
  Vec3 xi = Vec3::Zero();    // tangential spring (m)
  Index hint_a = 0, hint_b = 0;  // support-vertex hints
  bool warm = false;             // dir and hints come from a previous step
  // Results of the current step:
  ContactResult geo;
  Vec3 force = Vec3::Zero();  // force on b at geo.point (N); on a it is -force
  Vec3 torque = Vec3::Zero(); // extra torque on b (patch damping, N m); on a it is -torque
  double normal_force = 0;    // N

  std::uint64_t key() const {
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) |
           static_cast<std::uint32_t>(b);
  }
};

// True if the pair touches in the current step and so carries a force: the
// one criterion for "in contact" (World::contact_count, coordination numbers,
// contact output).
inline bool in_contact(const PairContact& pc) { return pc.geo.touching; }

struct State {
  double time = 0;        // s
  std::int64_t step = 0;
  std::vector<BodyState> bodies;
  std::vector<WallState> walls;
  std::vector<PairContact> pairs;       // grain-grain, sorted by (a, b)
  std::vector<PairContact> wall_pairs;  // wall-grain, sorted by (wall, grain)
  // Verlet-skin bookkeeping: positions at the last broadphase rebuild. Code
  // that moves grains by hand (not by stepping) sets rebuild_pairs.
  std::vector<Vec3> x_at_rebuild;
  bool rebuild_pairs = true;
};

}  // namespace grainlab
