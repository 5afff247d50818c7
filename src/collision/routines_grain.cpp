// Grain-grain pair routines: exact sphere-sphere; GJK/EPA sphere-polytope;
// polytope-polytope by the warm translated GJK (or GJK/EPA cold) with the
// patch's soft depth (narrowphase.h). The pair cache carries the last normal,
// the support hints and, for polytope pairs, the last GJK simplex
// (simplex_cache.h); a polytope pair is warm once it has been collided.
#include "collision/narrowphase.h"
#include "collision/pair_routines.h"

namespace grainlab::routines {

int sphere_sphere(const PosedShape& a, const PosedShape& b, PairCache&, PairCache*, SubContact* out) {
  out[0] = {collide(SphereShape{a.pos, a.radius}, SphereShape{b.pos, b.radius}), 0};
  return 1;
}

int sphere_polytope(const PosedShape& a, const PosedShape& b, PairCache& c, PairCache*, SubContact* out) {
  PolytopeShape pb{&b.geometry_as<ConvexPolytope>(), *b.rot, b.pos, b.scale, c.hint_b};
  out[0] = {collide_convex(SphereShape{a.pos, a.radius}, pb, c.dir), 0};
  c.hint_b = pb.hint;
  return 1;
}

int polytope_polytope(const PosedShape& a, const PosedShape& b, PairCache& c, PairCache*, SubContact* out) {
  PolytopeShape pa{&a.geometry_as<ConvexPolytope>(), *a.rot, a.pos, a.scale, c.hint_a};
  PolytopeShape pb{&b.geometry_as<ConvexPolytope>(), *b.rot, b.pos, b.scale, c.hint_b};
  out[0] = {collide_convex(pa, pb, c.dir, c.warm, &c.simplex), 0};
  c.hint_a = pa.hint;
  c.hint_b = pb.hint;
  c.warm = true;
  return 1;
}

}  // namespace grainlab::routines
