// Sphere-sphere contact geometry, four pairs at a time.
//
// For centres a, b and radii ra, rb:
//   d = b - a,  |d| = sqrt(d.d),  depth = (ra + rb) - |d|  (touching: depth > 0),
//   n = d / |d|  (+z for coincident centres: any direction separates them),
//   point = (a + b)/2 + (ra - rb)/2 n,
// midway between A's surface point a + ra n and B's b - rb n.
//
// Every sphere pair in grainlab goes through this one compiled function (the
// table's routine and a world of spheres' narrowphase alike, collide() in
// narrowphase.h using one lane): inlined into each caller, GCC would fuse
// a*b + c into FMAs differently in each place, and the same pair would get
// different bits from different paths. The lanes are independent, so a
// pair's result does not depend on its lane or its neighbours.
#pragma once

#include "collision/contact_result.h"

namespace grainlab {

// A sphere as four doubles side by side: centre x, y, z and radius (m), the
// layout of SphereShape and CompactPose.
using SphereXYZR = const double*;

struct SpherePairsOut {
  double depth[4];               // m; touching where > 0
  double nx[4], ny[4], nz[4];    // unit normal, a to b
  double px[4], py[4], pz[4];    // contact point (m)
};

// Lane l: the pair (a[l], b[l]). Each sphere is read as one 32-byte load
// (no copy into a staging struct: a 32-byte load of what narrower stores
// just wrote waits for them).
void sphere_pairs(const SphereXYZR a[4], const SphereXYZR b[4], SpherePairsOut& out);

// Lane l of `out` as a ContactResult.
inline ContactResult sphere_pair_result(const SpherePairsOut& out, int l) {
  ContactResult r;
  r.depth = out.depth[l];
  r.touching = r.depth > 0;
  r.normal = Vec3(out.nx[l], out.ny[l], out.nz[l]);
  r.point = Vec3(out.px[l], out.py[l], out.pz[l]);
  return r;
}

}  // namespace grainlab
