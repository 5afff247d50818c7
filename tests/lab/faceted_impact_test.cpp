// Angular grains falling onto the floor as they do in deposition (issue 10):
// an impact may lose energy, never gain it.
//
// Grains of the angular preset (the lab's crushed limestone: its shapes,
// material, density scaling, lubricated floor, deposition gravity 100 g and
// time step) fall 20 mm onto the floor, landing at 6.3 m/s, in random
// orientations, side by side 3 mm apart, so each meets only the floor. Each
// grain's kinetic plus potential energy E = KE + m g z (inertial mass,
// deposition gravity) can only fall: the contact's elastic energy is zero
// before and after each bounce, and the damping and the free flight create
// none. Free flight keeps E to about 1e-6 of E0 (the rotation step), so the
// bound is E <= E0 (1 + 1e-3).
//
// What it guards: with the soft depth D = kappa S3/S2 (collision/soft_depth.h
// before session 6) one deep vertex among many shallow ones made the sum of
// the vertex weights vanish, the contact force's line of action ran
// millimetres outside the grain, and one step's torque kick multiplied E.
// Measured, 60 drops for each of shape seeds 11, 1, 2, 3:
//   k = 2, from 20 mm: largest E/E0 1, 2.86, 1.11, 1;  from 50 mm: 3.1, 1651, 709, 1.007
//   k = 4, from 20 mm: 1, 1, 1, 1;                     from 50 mm: 1, 1.19, 1, 1
// The one gain left at 50 mm (10 m/s) is a grain spinning at 4.5e4 rad/s,
// 0.11 rad per step: its corner moves 56 um a step, more than the overlap,
// so no contact model resolves that impact at this step.
#include "core/rng.h"
#include "dynamics/world.h"
#include "lab/grain_library.h"
#include "lab/sand_presets.h"
#include "lab/specimen.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <vector>

using namespace grainlab;

namespace {

// One set of the preset's shapes (seed `shape_seed`), 60 grains in random
// orientations dropped from `height` (m); returns the largest E/E0.
double largest_energy_ratio(std::uint64_t shape_seed, double height) {
  LabSpec spec;
  apply_sand_preset(spec, "crushed-limestone");
  World w;
  Model& m = w.model;
  m.law = spec.material.law;
  const Index grain = m.add_material(spec.material.grain);
  Material wall = spec.material.grain;
  wall.friction = spec.material.wall_friction;
  const Index floor_material = m.add_material(wall);
  const std::vector<Index> shapes = add_grain_shapes(m, spec.grains, shape_seed, spec.numerics.threads);
  const int n = 60;
  const double pitch = 3e-3;
  Rng rng(12);
  for (int i = 0; i < n; ++i)
    w.add_body(shapes[static_cast<std::size_t>(i) % shapes.size()], grain, 1.0,
               Vec3((i % 8) * pitch, (i / 8) * pitch, height), rng.rotation());
  w.add_plane(Vec3::Zero(), Vec3::UnitZ(), floor_material, "floor");
  m.density_scale = 100;
  m.rescale_bodies();
  const double g = kDepositionGravity * kStandardGravity;  // acceleration of the inertial mass
  m.gravity = Vec3(0, 0, -g * m.density_scale);
  const double dt = spec.numerics.time_step_fraction * w.critical_time_step();

  const auto energy = [&](int i) {
    return kinetic_energy_of(m.bodies[i], w.state.bodies[i]) + m.bodies[i].mass * g * w.state.bodies[i].x.z();
  };
  std::vector<double> e0(n), e_max(n);
  for (int i = 0; i < n; ++i) e0[i] = e_max[i] = energy(i);
  const int steps = 9000;  // the fall takes ~2600 steps, then several bounces
  for (int s = 0; s < steps; ++s) {
    w.step(dt);
    for (int i = 0; i < n; ++i) e_max[i] = std::max(e_max[i], energy(i));
  }
  int landed = 0;
  double worst = 0;
  for (int i = 0; i < n; ++i) {
    worst = std::max(worst, e_max[i] / e0[i]);
    if (w.state.bodies[i].x.z() < 1e-3) ++landed;
  }
  EXPECT_GE(landed, n * 3 / 4) << "they land and bounce down within the run";
  return worst;
}

}  // namespace

TEST(FacetedImpact, AngularGrainsLandingAt6MetresPerSecondGainNoEnergy) {
  for (std::uint64_t seed : {1, 2}) {
    const double worst = largest_energy_ratio(seed, 20e-3);
    std::printf("shape seed %d: largest E/E0 over 60 drops from 20 mm: %.6f\n", static_cast<int>(seed), worst);
    EXPECT_LE(worst, 1 + 1e-3) << "shape seed " << seed;
  }
}
