// Wall-grain pair routines (the wall is shape a): exact plane-sphere,
// box-sphere and plane-polytope (depth-weighted centroid); box-polytope by the
// warm translated GJK (GJK/EPA cold), with the exact face point (narrowphase.h).
// A plane's outward normal is its local +z axis, q * z.
#include "collision/narrowphase.h"
#include "collision/pair_routines.h"

namespace grainlab::routines {

int plane_sphere(const PosedShape& a, const PosedShape& b, PairCache&, PairCache*, SubContact* out) {
  out[0] = {collide(PlaneShape{a.pos, *a.q * Vec3::UnitZ()}, SphereShape{b.pos, b.radius}), 0};
  return 1;
}

int plane_polytope(const PosedShape& a, const PosedShape& b, PairCache& c, PairCache*, SubContact* out) {
  const PlaneShape plane{a.pos, *a.q * Vec3::UnitZ()};
  PolytopeShape pb{b.hull, *b.rot, b.pos, b.scale, c.hint_b};
  out[0] = {collide(plane, pb), 0};
  c.hint_b = pb.hint;
  return 1;
}

int box_sphere(const PosedShape& a, const PosedShape& b, PairCache&, PairCache*, SubContact* out) {
  out[0] = {collide(BoxShape{*a.rot, a.pos, a.half}, SphereShape{b.pos, b.radius}), 0};
  return 1;
}

int box_polytope(const PosedShape& a, const PosedShape& b, PairCache& c, PairCache*, SubContact* out) {
  const BoxShape box{*a.rot, a.pos, a.half};
  PolytopeShape pb{b.hull, *b.rot, b.pos, b.scale, c.hint_b};
  out[0] = {collide_convex(box, pb, c.dir, c.warm), 0};
  c.hint_b = pb.hint;
  c.warm = true;
  return 1;
}

}  // namespace grainlab::routines
