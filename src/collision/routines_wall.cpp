// Wall-grain pair routines (the wall is shape a): exact plane-sphere,
// box-sphere and plane-polytope (depth-weighted centroid); box-polytope as the
// plane of one face when the grain's bounding sphere lies over that face,
// else by the warm translated GJK (GJK/EPA cold), with the exact face point
// (narrowphase.h).
// A plane's outward normal is its local +z axis, q * z; a box's geometry is
// its half extents (a Vec3, m).
#include "collision/narrowphase.h"
#include "collision/pair_routines.h"

#include <cmath>

namespace grainlab::routines {

int plane_sphere(const PosedShape& a, const PosedShape& b, PairCache&, PairCache*, SubContact* out) {
  out[0] = {collide(PlaneShape{a.pos, *a.q * Vec3::UnitZ()}, SphereShape{b.pos, b.radius}), 0};
  return 1;
}

int plane_polytope(const PosedShape& a, const PosedShape& b, PairCache& c, PairCache*, SubContact* out) {
  const PlaneShape plane{a.pos, *a.q * Vec3::UnitZ()};
  PolytopeShape pb{&b.geometry_as<ConvexPolytope>(), *b.rot, b.pos, b.scale, c.hint_b};
  out[0] = {collide(plane, pb), 0};
  c.hint_b = pb.hint;
  return 1;
}

int box_sphere(const PosedShape& a, const PosedShape& b, PairCache&, PairCache*, SubContact* out) {
  out[0] = {collide(BoxShape{*a.rot, a.pos, a.geometry_as<Vec3>()}, SphereShape{b.pos, b.radius}), 0};
  return 1;
}

namespace {

// The face of box a whose column holds the whole bounding sphere of b (centre
// p, radius r, in the box's frame): |p_j| + r <= h_j across the face's two axes
// j, and b not through to the opposite face. Inside that column the solid box
// is exactly the half-space behind the face, so b meets the box as it meets
// the face's plane. Returns the axis, or -1 (an edge or corner may be near).
int face_column(const Vec3& p, double r, const Vec3& h) {
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    if (std::abs(p[i]) + r <= h[i] && std::abs(p[j]) + r <= h[j] && std::abs(p[k]) - r > -h[k]) return k;
  }
  return -1;
}

}  // namespace

int box_polytope(const PosedShape& a, const PosedShape& b, PairCache& c, PairCache*, SubContact* out) {
  const ConvexPolytope& hull = b.geometry_as<ConvexPolytope>();
  const Vec3& half = a.geometry_as<Vec3>();
  PolytopeShape pb{&hull, *b.rot, b.pos, b.scale, c.hint_b};
  const Vec3 p = a.rot->transpose() * (b.pos - a.pos);
  const int k = face_column(p, b.scale * hull.bounding_radius(), half);
  if (k >= 0) {
    // The plane routine, which the GJK/EPA path below also ends in for a
    // contact on a face; no GJK is run, so the next one starts cold.
    const Vec3 n = (p[k] >= 0 ? 1.0 : -1.0) * a.rot->col(k);
    out[0] = {collide(PlaneShape{a.pos + half[k] * n, n}, pb), 0};
    c.hint_b = pb.hint;
    c.warm = false;
    return 1;
  }
  out[0] = {collide_convex(BoxShape{*a.rot, a.pos, half}, pb, c.dir, c.warm), 0};
  c.hint_b = pb.hint;
  c.warm = true;
  return 1;
}

}  // namespace grainlab::routines
