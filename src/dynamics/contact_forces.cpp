// The forces phase of World::step (see contact_forces.h).
//
// Determinism: blocks of four contacts are fixed by index, so the thread
// count changes nothing, and the sums per body and per wall are serial.
#include "dynamics/contact_forces.h"

#include "core/parallel.h"
#include "dynamics/contact_lanes.h"
#include "dynamics/contact_law.h"
#include "dynamics/laws/registry.h"

#include <algorithm>

namespace grainlab {

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
// Out of line: the batched sphere pass and evaluate_all call one compiled
// body, so that both give a contact the same bits (inlined at each caller,
// GCC may contract a*b + c into FMAs differently; collision/sphere_pairs.h).
template <typename Law, typename Sides>
[[gnu::noinline]] void evaluate_block(std::vector<Contact>& list, std::size_t first, double dt, const Sides& sides) {
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
    c.m_eff[l] = s.m_eff, c.r_eff[l] = s.r_eff, c.gain[l] = pc.geo.gain, c.share[l] = pc.geo.share;
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

template <typename Law>
void forces_with(const ForceStep& s, double dt, std::vector<Vec3>& force, std::vector<Vec3>& torque) {
  const Model& model = s.model;
  State& state = s.state;
  const auto pair = [&](Index ma, Index mb) -> const PairCoefficients& {
    return s.pair_table[static_cast<std::size_t>(ma) * model.materials.size() + mb];
  };
  // Per contact (all touching), four at a time, in parallel: the force on b at the contact point.
  const auto grain_sides = [&](const Contact& pc) {
    const BodyModel &ma = model.bodies[pc.a], &mb = model.bodies[pc.b];
    const BodyState &sa = state.bodies[pc.a], &sb = state.bodies[pc.b];
    const Vec3& p = pc.geo.point;
    return ContactSides{&pair(ma.material, mb.material),
                        (sb.v + sb.w.cross(p - sb.x)) - (sa.v + sa.w.cross(p - sa.x)), sb.w - sa.w,
                        ma.mass * mb.mass / (ma.mass + mb.mass), ma.radius * mb.radius / (ma.radius + mb.radius)};
  };
  // Each body's resultant starts from its weight; a grain-grain contact's
  // force and torque are added to both of its grains, serially in contact
  // order (so independent of the thread count).
  const std::size_t n = state.bodies.size();
  const Vec3 g = s.gravity;
  for (std::size_t i = 0; i < n; ++i) {
    force[i] = model.bodies[i].gravity_mass * g;
    torque[i].setZero();
  }
  for (WallState& w : state.walls) w.force.setZero();
  const auto add_grain_contact = [&](const Contact& pc) {
    force[pc.b] += pc.force;
    force[pc.a] -= pc.force;
    torque[pc.b] += (pc.geo.point - state.bodies[pc.b].x).cross(pc.force) + pc.torque;
    torque[pc.a] -= (pc.geo.point - state.bodies[pc.a].x).cross(pc.force) + pc.torque;
  };
  if (GrainContactSource* source = s.source) {
    // Made a batch at a time: each batch pushed and summed while in cache.
    std::vector<Contact>& list = *source->list;
    constexpr std::size_t kBatch = 8 * kLanes;
    for (std::size_t first = list.size(), made; (made = source->more(kBatch)) > 0; first += made) {
      for (std::size_t k = first; k < first + made; k += kLanes) evaluate_block<Law>(list, k, dt, grain_sides);
      for (std::size_t k = first; k < first + made; ++k) add_grain_contact(list[k]);
    }
  } else {
    evaluate_all<Law>(state.contacts, dt, grain_sides, s.threads, s.serial_below);
    for (const Contact& pc : state.contacts) add_grain_contact(pc);
  }

  // Walls: infinite mass and radius, translating at their prescribed velocity.
  const auto wall_sides = [&](const Contact& pc) {
    const BodyModel& mb = model.bodies[pc.b];
    const BodyState& sb = state.bodies[pc.b];
    const Vec3& p = pc.geo.point;
    return ContactSides{&pair(model.walls[pc.a].material, mb.material),
                        (sb.v + sb.w.cross(p - sb.x)) - state.walls[pc.a].v, sb.w, mb.mass, mb.radius};
  };
  evaluate_all<Law>(state.wall_contacts, dt, wall_sides, s.threads, s.serial_below);

  for (const Contact& pc : state.wall_contacts) {
    force[pc.b] += pc.force;
    torque[pc.b] += (pc.geo.point - state.bodies[pc.b].x).cross(pc.force) + pc.torque;
    state.walls[pc.a].force -= pc.force;
  }
}

}  // namespace

void contact_forces(const ForceStep& s, double dt, std::vector<Vec3>& force, std::vector<Vec3>& torque) {
  // One force loop per registered law: the law is chosen once per step, and
  // its coefficients are inlined into the loop.
  with_law(s.model.law, [&]<typename Law>() { forces_with<Law>(s, dt, force, torque); });
}

}  // namespace grainlab
