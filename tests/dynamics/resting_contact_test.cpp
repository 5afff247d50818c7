// Faceted grains at rest (issue 10 item 1): a frictionless, undamped box
// rocking on a flat plane, or on another box, must not gain energy.
//
// Energy: E = sum of kinetic energies - sum m g.x + sum over contacts of the
// elastic energy u(D) of the law at the contact's depth D (Hertz: u =
// (2/5) f(D) D). With a conservative contact force the semi-implicit Euler
// step keeps E within a bounded oscillation (O(dt) of the rocking energy); a
// force that is not the gradient of a potential (a point of application that
// is not the potential's lever arm) pumps energy in every rocking cycle and E
// grows without bound.
#include "dynamics/laws/registry.h"
#include "dynamics/world.h"
#include "geometry/primitives.h"
#include "lab/rest_criteria.h"
#include "lab/settling_bed.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <algorithm>
#include <vector>

using namespace grainlab;

namespace {

// Orientation taking the shape's principal frame onto the world axes of the box
// with half sides `half` (all distinct), then rotated by `tilt`.
Quat box_orientation(const World& w, Index shape, const Vec3& half, const Quat& tilt) {
  Vec3 extent = Vec3::Zero();
  for (const Vec3& v : w.model.shapes[shape].mesh.vertices) extent = extent.cwiseMax(v.cwiseAbs());
  Mat3 r = Mat3::Zero();
  for (int i = 0; i < 3; ++i) {
    int j = 0;
    (half.array() - extent[i]).abs().minCoeff(&j);
    r(j, i) = 1;
  }
  if (r.determinant() < 0) r.col(0) = -r.col(0);
  return tilt * Quat(r);
}

// Height of the centre of a shape in orientation q whose lowest vertex is at 0 (m).
double lift_to_touch(const World& w, Index shape, const Quat& q) {
  double low = 0;
  for (const Vec3& v : w.model.shapes[shape].mesh.vertices) low = std::min(low, (q * v).z());
  return -low;
}

// Total energy (J): kinetic + gravitational + the Hertz law's elastic energy.
double total_energy(const World& w) {
  double e = w.kinetic_energy();
  for (std::size_t i = 0; i < w.state.bodies.size(); ++i)
    e -= w.model.bodies[i].gravity_mass * w.gravity().dot(w.state.bodies[i].x);
  const auto elastic = [&](const Contact& c, double r_eff, double m_eff, Index ma, Index mb) {
    if (!c.geo.touching) return 0.0;
    const LawCoefficients k = HertzMaterialLaw::at(w.model.pair(ma, mb), c.geo.depth, r_eff, m_eff);
    return HertzMaterialLaw::elastic_energy(k.k_n * c.geo.depth, c.geo.depth);
  };
  for (const Contact& c : w.state.contacts) {
    const BodyModel &a = w.model.bodies[c.a], &b = w.model.bodies[c.b];
    e += elastic(c, a.radius * b.radius / (a.radius + b.radius), a.mass * b.mass / (a.mass + b.mass),
                 a.material, b.material);
  }
  for (const Contact& c : w.state.wall_contacts) {
    const BodyModel& b = w.model.bodies[c.b];
    e += elastic(c, b.radius, b.mass, w.model.walls[c.a].material, b.material);
  }
  return e;
}

struct Drift {
  double gain;    // largest E(t) - E(0) over the run, over the initial rocking energy
  double spread;  // (max E - min E) over the initial rocking energy
};

// Runs `steps` steps and measures the energy against its start.
Drift run_energy(World& w, double dt, int steps, double rocking_energy) {
  w.step(dt);
  const double e0 = total_energy(w);
  double e_max = e0, e_min = e0;
  for (int i = 0; i < steps; ++i) {
    w.step(dt);
    const double e = total_energy(w);
    e_max = std::max(e_max, e);
    e_min = std::min(e_min, e);
    if (std::getenv("GL_TRACE") && i % 5000 == 0) std::printf("%d %.6g\n", i, (e - e0) / rocking_energy);
  }
  return {(e_max - e0) / rocking_energy, (e_max - e_min) / rocking_energy};
}

Material rock() {
  Material m;
  m.density = 2650;
  m.youngs_modulus = 1e7;
  m.poisson_ratio = 0.3;
  m.restitution = 1.0;  // no damping
  m.friction = 0.0;
  return m;
}

}  // namespace

// A box (half sides 1.0 x 0.8 x 0.6 mm) lies on its largest face on a plane,
// tilted by 0.01 rad about an axis off the principal axes so that it rocks
// about two axes; nothing damps it.
TEST(RestingContact, UndampedBoxOnPlaneGainsNoEnergy) {
  World w;
  w.model.law = contact_law<HertzMaterialLaw>();
  const Index m = w.model.add_material(rock());
  const Vec3 h(1.0e-3, 0.8e-3, 0.6e-3);
  const Index box = w.model.add_mesh_shape(box_mesh(h.x(), h.y(), h.z()), "box");
  w.add_plane(Vec3::Zero(), Vec3::UnitZ(), m, "floor");
  const Quat tilt(Eigen::AngleAxisd(0.01, Vec3(1, 0.6, 0).normalized()));
  const Quat q = box_orientation(w, box, h, tilt);
  w.add_body(box, m, 1.0, Vec3(0, 0, lift_to_touch(w, box, q)), q);
  const double dt = 0.1 * w.critical_time_step();
  // Rocking energy: the lift of the centre by the tilt, m g h_x sin(0.01) roughly.
  const double rocking = w.model.bodies[0].mass * 9.81 * h.x() * 0.01;
  const Drift d = run_energy(w, dt, 100000, rocking);
  RecordProperty("gain", std::to_string(d.gain));
  std::printf("box on plane: energy gain %.3g, spread %.3g of the rocking energy\n", d.gain, d.spread);
  // Measured 0.094 (spread 0.18); the depth-weighted centroid it replaces: 16.5.
  EXPECT_LT(d.gain, 0.2);
}

// The same box resting on a larger box lying on the plane.
TEST(RestingContact, UndampedBoxOnBoxGainsNoEnergy) {
  World w;
  w.model.law = contact_law<HertzMaterialLaw>();
  const Index m = w.model.add_material(rock());
  const Vec3 hb(2.0e-3, 1.7e-3, 0.5e-3), h(1.0e-3, 0.8e-3, 0.6e-3);
  const Index big = w.model.add_mesh_shape(box_mesh(hb.x(), hb.y(), hb.z()), "big");
  const Index box = w.model.add_mesh_shape(box_mesh(h.x(), h.y(), h.z()), "box");
  w.add_plane(Vec3::Zero(), Vec3::UnitZ(), m, "floor");
  w.add_body(big, m, 1.0, Vec3(0, 0, hb.z() - 2e-7), box_orientation(w, big, hb, Quat::Identity()));
  const Quat tilt(Eigen::AngleAxisd(0.01, Vec3(1, 0.6, 0).normalized()));
  const Quat q = box_orientation(w, box, h, tilt);
  w.add_body(box, m, 1.0, Vec3(0.2e-3, -0.1e-3, 2 * hb.z() + lift_to_touch(w, box, q)), q);
  const double dt = 0.1 * w.critical_time_step();
  const double rocking = w.model.bodies[1].mass * 9.81 * h.x() * 0.01;
  const Drift d = run_energy(w, dt, 100000, rocking);
  std::printf("box on box: energy gain %.3g, spread %.3g of the rocking energy\n", d.gain, d.spread);
  // Measured 0.054 (spread 0.12); the depth-weighted centroid it replaces: 97.
  EXPECT_LT(d.gain, 0.2);
}

// A frictionless, damped bed of 300 faceted grains (40-face hulls) dropped
// into a box under gravity comes to rest: the kinetic energy falls below 1e-8
// of its peak and the instantaneous unbalanced-force ratio below 1e-2.
//
// Issue 10 item 1. Before session 8 this failed (KE 8.9e-6 of peak, ratio
// 0.092 at 0.3 s, both flat): half the contacts were point contacts at PD
// (edges crossing), whose potential has kinks that pumped energy in
// (bench_contact_energy). With the edge soft depth (soft_depth.h) the bed
// comes to rest; measured: both criteria met at 0.93 s (step 40,100; the
// ratio is below 1e-2 from 0.28 s, the kinetic energy falls slowly at the
// end). The limit of 1.5 s leaves room for another machine's rounding.
TEST(RestingContact, FrictionlessFacetedBedComesToRest) {
  SettlingBedSpec spec = frictionless_faceted_bed_spec();
  SettlingBed bed = make_settling_bed(spec);
  World& w = bed.world;
  w.settings.threads = 2;
  w.model.gravity *= 10;  // lands in few steps
  const double dt = 0.2 * w.critical_time_step();
  double ke_peak = 0, ke = 1, ub = 1;
  // Falling and piling up take ~0.05 s; then the bed must become still.
  const int steps = static_cast<int>(1.5 / dt);
  int i = 0;
  for (; i < steps; ++i) {
    w.step(dt);
    ke_peak = std::max(ke_peak, w.kinetic_energy());
    if (w.state.time < 0.05 || i % 100 != 0) continue;
    ke = w.kinetic_energy() / ke_peak;
    ub = unbalanced_force_ratio(w);
    if (i % 2000 == 0) std::printf("step %d  ke/peak %.3g  unbalanced %.3g\n", i, ke, ub);
    if (ke < 1e-8 && ub < 1e-2) break;
  }
  std::printf("bed: at rest at step %d of %d (t = %.3f s): ke/peak %.3g unbalanced %.3g\n", i, steps, w.state.time, ke, ub);
  EXPECT_LT(ke, 1e-8);
  EXPECT_LT(ub, 1e-2);
}
