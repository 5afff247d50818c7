// Does the faceted contact conserve energy? An audit for issue 10 item 1
// (faceted grains that never come to rest). Not a test: it prints figures.
//
//   build/bench_contact_energy [--grains N] [--hull-points P] [--seed S] [--steps K] [--spheres]
//
// --spheres runs the same bed of spheres: the control, whose contacts are
// smooth, so its drift shows the audit's own resolution.
//
// The scene is the frictionless faceted bed of RestingContact's disabled
// test: 300 grains of 40-face hulls, E = 1e7 Pa, restitution 0.3, 10 g, step
// 0.2 of the critical one, settled for 0.3 s with damping. Then the damping
// is switched off (restitution 1) and the bed runs K more steps. A
// conservative contact model keeps the total energy
//     E = kinetic + gravitational + sum over contacts of u(depth)
// bounded (the semi-implicit Euler step conserves a nearby energy: no drift);
// a potential with jumps, or with V-shaped kinks the step crosses, drifts.
//
// Attribution. Over one step a contact's energy error is
//     e = u(x1) - u(x0) + dt (P(x0) + P(x1)) / 2,
// u its elastic energy at the start positions x0 and the end positions x1,
// P the power of its elastic wrench, F . v_rel(point) + tau_twist . w_rel,
// both with the velocities that carry x0 to x1: the trapezoidal rule for the
// work of the contact, exact to O(dt^3) where the force is smooth. Summed
// over the run by the contact's kind: a point contact at the penetration
// depth (gain 1, no spread: PD, e.g. edge across edge) or the soft depth of
// the vertices inside (soft_depth.h). A contact appearing or vanishing
// counts with u = 0 on the other side.
#include "bench_args.h"
#include "core/wait_policy.h"
#include "lab/rest_criteria.h"
#include "lab/settling_bed.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstring>
#include <map>
#include <string>
#include <tuple>
#include <vector>

using namespace grainlab;

namespace {

// A contact's identity across steps: (a, b, sub); a wall pair has a = -1 - wall.
using Key = std::tuple<int, int, int>;

enum Kind { kPoint, kSoft, kKindCount };

struct Snapshot {
  double energy = 0;  // elastic energy u (J)
  Vec3 force, twist_torque, point;
  Kind kind = kPoint;
};

std::map<Key, Snapshot> snapshot(const World& w) {
  std::map<Key, Snapshot> out;
  for (const bool walls : {false, true}) {
    for (const Contact& c : walls ? w.state.wall_contacts : w.state.contacts) {
      Snapshot s;
      const double elastic = c.normal_force / c.geo.gain;  // no damping: the law's elastic force at depth
      s.energy = w.model.law->elastic_energy(elastic, c.geo.depth);
      s.force = c.normal_force * c.geo.normal;
      s.twist_torque = elastic * c.geo.twist;
      s.point = c.geo.point;
      s.kind = (c.geo.gain == 1.0 && c.geo.spread == 0.0) ? kPoint : kSoft;
      out[{walls ? -1 - static_cast<int>(c.a) : static_cast<int>(c.a), static_cast<int>(c.b), c.sub}] = s;
    }
  }
  return out;
}

// Power of a contact's elastic wrench on b relative to a, with velocities v.
double power(const Key& k, const Snapshot& s, const std::vector<BodyState>& v) {
  const BodyState& b = v[static_cast<std::size_t>(std::get<1>(k))];
  Vec3 vel = b.v + b.w.cross(s.point - b.x), omega = b.w;
  if (std::get<0>(k) >= 0) {
    const BodyState& a = v[static_cast<std::size_t>(std::get<0>(k))];
    vel -= a.v + a.w.cross(s.point - a.x);
    omega -= a.w;
  }
  return s.force.dot(vel) + s.twist_torque.dot(omega);
}

double total_energy(const World& w, const std::map<Key, Snapshot>& contacts) {
  double e = w.kinetic_energy();
  for (std::size_t i = 0; i < w.state.bodies.size(); ++i)
    e -= w.model.bodies[i].gravity_mass * w.gravity().dot(w.state.bodies[i].x);
  for (const auto& [key, s] : contacts) e += s.energy;
  return e;
}

}  // namespace

int main(int argc, char** argv) {
  grainlab::bench::check_args(argc, argv, "[--grains N] [--hull-points P] [--seed S] [--steps K] [--spheres]",
                              {"--grains", "--hull-points", "--seed", "--steps"}, {"--spheres"});
  grainlab::use_passive_wait_by_default(argv);
  SettlingBedSpec spec = frictionless_faceted_bed_spec();
  int steps = 2000;
  for (int i = 1; i < argc; ++i) {
    const bool value = i + 1 < argc;
    if (!std::strcmp(argv[i], "--spheres")) spec.spheres = true;  // the audit's control: smooth contacts
    else if (value && !std::strcmp(argv[i], "--grains")) spec.grains = std::stoi(argv[++i]);
    else if (value && !std::strcmp(argv[i], "--hull-points")) spec.hull_points = std::stoi(argv[++i]);
    else if (value && !std::strcmp(argv[i], "--seed")) spec.seed = std::stoull(argv[++i]);
    else if (value && !std::strcmp(argv[i], "--steps")) steps = std::stoi(argv[++i]);
  }
  SettlingBed bed = make_settling_bed(spec);
  World& w = bed.world;
  w.model.gravity *= 10;
  const double dt = 0.2 * w.critical_time_step();
  double ke_peak = 0;
  for (int i = 0, n = static_cast<int>(0.3 / dt); i < n; ++i) {
    w.step(dt);
    ke_peak = std::max(ke_peak, w.kinetic_energy());
  }
  fmt::print("frictionless bed of {} {} (seed {}), settled 0.3 s with damping:\n", spec.grains,
             spec.spheres ? "spheres" : fmt::format("grains of {}-point hulls", spec.hull_points), spec.seed);
  fmt::print("  kinetic energy {:.3g} of its peak, unbalanced force ratio {:.3g}\n", w.kinetic_energy() / ke_peak,
             unbalanced_force_ratio(w));

  for (Material& m : w.model.materials) m.restitution = 1;  // no damping from here on
  w.model.finalize();
  w.set_overrides({});
  w.step(dt);
  std::map<Key, Snapshot> before = snapshot(w), after;
  std::vector<BodyState> carry = w.state.bodies;  // velocities that carry these positions to the next
  double elastic = 0;
  for (const auto& [key, s] : before) elastic += s.energy;
  const double e0 = total_energy(w, before), ke0 = w.kinetic_energy();
  std::array<double, kKindCount> error{}, count{};
  std::map<Key, double> by_pair;
  fmt::print("undamped, {} steps; energies in J (elastic energy in the contacts {:.3g}):\n", steps, elastic);
  fmt::print("  {:>6}  {:>10}  {:>10}  {:>14}  {:>14}\n", "step", "E - E0", "kinetic", "error PD point", "error soft");
  for (int s = 1; s <= steps; ++s) {
    w.step(dt);
    after = snapshot(w);
    for (const auto& [key, snap] : after) {
      const auto it = before.find(key);
      const double e = snap.energy - (it == before.end() ? 0.0 : it->second.energy) +
                       0.5 * dt * ((it == before.end() ? 0.0 : power(key, it->second, carry)) + power(key, snap, carry));
      error[snap.kind] += e;
      count[snap.kind] += 1;
      by_pair[key] += e;
    }
    for (const auto& [key, snap] : before) {
      if (after.count(key)) continue;
      const double e = -snap.energy + 0.5 * dt * power(key, snap, carry);
      error[snap.kind] += e;
      by_pair[key] += e;
    }
    before.swap(after);
    carry = w.state.bodies;
    if (s % (steps / 10 > 0 ? steps / 10 : 1) == 0)
      fmt::print("  {:>6}  {:>10.3g}  {:>10.3g}  {:>14.3g}  {:>14.3g}\n", s, total_energy(w, before) - e0,
                 w.kinetic_energy(), error[kPoint], error[kSoft]);
  }
  double gained = 0, lost = 0;
  for (const auto& [key, e] : by_pair) (e > 0 ? gained : lost) += e;
  fmt::print("energy drift {:.3g} J per 1000 steps ({:.3g} of the contacts' elastic energy); kinetic {:.3g} -> {:.3g} J\n",
             (total_energy(w, before) - e0) * 1000.0 / steps, (total_energy(w, before) - e0) * 1000.0 / steps / elastic,
             ke0, w.kinetic_energy());
  fmt::print("by kind: point contacts (PD) {:.3g} J ({:.0f} contact-steps), soft depth {:.3g} J ({:.0f});\n",
             error[kPoint], count[kPoint], error[kSoft], count[kSoft]);
  fmt::print("by pair: {:.3g} J gained by the pairs that gained, {:.3g} J by those that lost\n", gained, lost);
}
