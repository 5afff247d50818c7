// Exact box-sphere (a box wall against a bead), replacing GJK/EPA for the
// commonest wall pair of a sphere lab.
//
// In the box's frame the sphere's centre is c = R^T (x - p). Outside the box
// (some |c_i| > h_i) the closest box point is q = clamp(c, -h, h), the
// separation s = |c - q| and the normal n = (c - q)/s: depth = r - s.
// Inside (every |c_i| <= h_i) the shortest way out is through the face of
// least clearance m = min_i (h_i - |c_i|), along its axis with c_i's sign
// (+ on a tie at the centre): depth = r + m, and q is c projected onto that
// face. Both are the minimum translation that separates the shapes (EPA's
// answer, without its iterations). The contact point is midway between the
// box's surface point q and the sphere's, x - r n.
#include "collision/narrowphase.h"

#include <cmath>

namespace grainlab {

ContactResult collide(const BoxShape& a, const SphereShape& b) {
  const Vec3 c = a.rot.transpose() * (b.pos - a.pos);
  const Vec3 q = c.cwiseMax(-a.half).cwiseMin(a.half);
  Vec3 n_local;
  Vec3 surface = q;
  ContactResult r;
  const Vec3 gap = c - q;
  const double s2 = gap.squaredNorm();
  if (s2 > 0) {
    const double s = std::sqrt(s2);
    n_local = gap / s;
    r.depth = b.radius - s;
  } else {
    int axis = 0;
    double clearance = a.half.x() - std::abs(c.x());
    for (int i = 1; i < 3; ++i) {
      const double m = a.half[i] - std::abs(c[i]);
      if (m < clearance) {
        clearance = m;
        axis = i;
      }
    }
    const double sign = c[axis] >= 0 ? 1.0 : -1.0;
    n_local = Vec3::Zero();
    n_local[axis] = sign;
    surface[axis] = sign * a.half[axis];
    r.depth = b.radius + clearance;
  }
  r.normal = a.rot * n_local;
  r.touching = r.depth > 0;
  const Vec3 q_world = a.pos + a.rot * surface;
  r.point = 0.5 * (q_world + (b.pos - b.radius * r.normal));
  return r;
}

}  // namespace grainlab
