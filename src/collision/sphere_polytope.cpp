// Sphere against polytope, by GJK/EPA on the support maps (mixed scenes are rare).
#include "collision/gjk.h"
#include "collision/narrowphase.h"

namespace grainlab {

ContactResult collide_convex(const SphereShape& a, const PolytopeShape& b, Vec3& dir) {
  return gjk_epa(a, b, dir);
}

}  // namespace grainlab
