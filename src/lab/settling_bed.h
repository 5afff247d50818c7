// The settling-bed scene: grains dropped from a loose lattice into an open box
// (floor and four side walls) come to rest under gravity. Shared by the tests
// and the benchmarks.
#pragma once

#include "dynamics/world.h"

#include <cstdint>
#include <string>

namespace grainlab {

struct SettlingBedSpec {
  int grains = 300;
  bool spheres = false;           // glass beads instead of convex grains
  double radius = 2e-3;           // volume-equivalent radius (m), +-10 % spread
  int shape_count = 8;            // distinct convex shapes in the library
  int hull_points = 1002;         // per convex shape (about 2n-4 hull faces)
  double spacing = 1.05;          // lattice spacing / grain bounding diameter
  int columns = 0;                // lattice columns per side (0: about cbrt(grains)*1.3)
  std::uint64_t seed = 1;
  ContactLaw law;  // a registered law; default hertz-material
  Material material = [] {
    Material m;
    m.name = "bed";
    m.density = 2650;
    m.youngs_modulus = 5e6;  // soft, so a bed settles in few steps; overlaps stay < 1 %
    m.poisson_ratio = 0.3;
    m.restitution = 0.3;
    m.friction = 0.4;
    return m;
  }();
};

struct SettlingBed {
  World world;
  double box_half_width = 0;  // the side walls are at x, y = +-box_half_width (m)
  double max_radius = 0;      // largest bounding radius (m)
};

SettlingBed make_settling_bed(const SettlingBedSpec& spec);

// The frictionless faceted bed of issue 10 item 1 (the test
// RestingContact.FrictionlessFacetedBedComesToRest and bench_contact_energy):
// 300 grains of 40-face hulls, E = 1e7 Pa, restitution 0.3, no friction, seed 5.
SettlingBedSpec frictionless_faceted_bed_spec();

// True if every grain's centre is inside the box (above the floor, within the walls).
bool all_grains_inside(const SettlingBed& bed);

// Largest grain-grain or grain-wall overlap relative to the smaller grain's
// equivalent radius, over the current contacts.
double max_relative_overlap(const World& world);

}  // namespace grainlab
