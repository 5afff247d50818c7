// The contact of two touching polytopes (see narrowphase.h): the soft depth
// of soft_depth.h over the vertices of each body lying inside the other.
//
// A vertex x of A is inside B iff it is below every face plane of B; its
// depth is its distance inside B's nearest face plane (for a point inside a
// convex body, the distance to its boundary), a continuous function of the
// two poses, zero when x enters. Only faces near the contact are tried: the
// faces through B's vertices below A's supporting plane (along the point
// contact's normal n). B above that plane lies in a half space that A's
// points do not enter, and B's part below it is bounded by exactly those
// faces, so a vertex of A is inside B iff it is below them all.
//
// GJK/EPA (or the warm translated GJK) still gives the normal, the
// penetration depth PD and the candidates; the pair's potential is
// u(max(PD, D)): where no vertex is inside (edge across edge), PD at the
// witness points.
#include "collision/narrowphase.h"
#include "collision/soft_depth.h"

#include <cstdint>
#include <limits>
#include <vector>

namespace grainlab {

namespace {

struct Walk {
  std::vector<std::uint32_t> stamp;
  std::uint32_t generation = 0;
  void begin(std::size_t n) {
    if (stamp.size() < n) stamp.assign(n, 0);
    if (++generation == 0) {
      std::fill(stamp.begin(), stamp.end(), 0u);
      generation = 1;
    }
  }
  bool mark(Index i) {
    if (stamp[i] == generation) return false;
    stamp[i] = generation;
    return true;
  }
};

constexpr std::size_t kMaxPatchVertices = 512;

// Vertices v of `poly` with excess(v) = base + dot(v, dir) > 0, by a breadth-first
// walk from `start` (where the excess is largest); the set is connected in the
// edge graph (see analytic.cpp). Returns false if there are too many.
bool collect(const ConvexPolytope& poly, Index start, const Vec3& dir, double base, Walk& w,
             std::vector<Index>& out) {
  out.clear();
  w.begin(poly.size());
  out.push_back(start);
  w.mark(start);
  for (std::size_t q = 0; q < out.size(); ++q) {
    for (const Index* it = poly.neighbours_begin(out[q]); it != poly.neighbours_end(out[q]); ++it) {
      if (!w.mark(*it)) continue;
      if (base + poly.vertex(*it).dot(dir) > 0) {
        out.push_back(*it);
        if (out.size() > kMaxPatchVertices) return false;
      }
    }
  }
  return true;
}

// Planes of `poly` incident to the listed vertices, each once.
void gather_planes(const ConvexPolytope& poly, const std::vector<Index>& verts, Walk& w,
                   std::vector<Index>& out) {
  out.clear();
  w.begin(poly.planes().size());
  for (const Index v : verts)
    for (const Index* it = poly.planes_begin(v); it != poly.planes_end(v); ++it)
      if (w.mark(*it)) out.push_back(*it);
}

// Adds the vertices `verts` of `s` lying inside `o` to the soft depth: depth =
// distance inside o's nearest face plane among `o_planes`, pushed out along
// that plane's normal; `sign` is +1 if s is B (the push on B), -1 if s is A
// (the reaction on B).
void add_side(const PolytopeShape& s, const std::vector<Index>& verts, const PolytopeShape& o,
              const std::vector<Index>& o_planes, double sign, SoftDepth& soft) {
  const ConvexPolytope& poly = *s.poly;
  const auto& planes = o.poly->planes();
  const Mat3 to_o = o.rot.transpose() * s.rot * (s.scale / o.scale);  // local s -> local o
  const Vec3 off = o.rot.transpose() * (s.pos - o.pos) / o.scale;
  for (const Index v : verts) {
    const Vec3& pv = poly.vertex(v);
    const Vec3 xl = to_o * pv + off;
    double d = std::numeric_limits<double>::infinity();
    Index best = 0;
    for (const Index k : o_planes) {
      const double dk = planes[k].c - planes[k].m.dot(xl);
      if (dk < d) d = dk, best = k;
    }
    if (d > 0 && d < std::numeric_limits<double>::infinity()) {
      const Vec3 x = s.pos + s.scale * (s.rot * pv), m = o.rot * planes[best].m;
      soft.add(x, d * o.scale, sign * m, x);
    }
  }
}

}  // namespace

void contact_patch(const PolytopeShape& a, const PolytopeShape& b, ContactResult& r) {
  if (!r.touching) return;
  const ConvexPolytope &pa = *a.poly, &pb = *b.poly;
  if (pa.planes().empty() || pb.planes().empty()) return;
  const Vec3 n = r.normal;
  // Height along n: h = h0 + dot(v_local, nl).
  const Vec3 nla = a.scale * (a.rot.transpose() * n), nlb = b.scale * (b.rot.transpose() * n);
  const double ha0 = n.dot(a.pos), hb0 = n.dot(b.pos);
  const Index sa = pa.support_index(nla, a.hint), sb = pb.support_index(-nlb, b.hint);
  const double top_a = ha0 + pa.vertex(sa).dot(nla);  // A's supporting plane
  const double bot_b = hb0 + pb.vertex(sb).dot(nlb);  // B's supporting plane
  if (!(top_a > bot_b)) return;

  // Candidates: A's vertices above B's supporting plane, B's below A's; the
  // faces that can bound the overlap are the faces through them.
  thread_local Walk walk;
  thread_local std::vector<Index> va, vb, qa, qb;
  if (!collect(pa, sa, nla, ha0 - bot_b, walk, va)) return;
  if (!collect(pb, sb, -nlb, top_a - hb0, walk, vb)) return;
  gather_planes(pa, va, walk, qa);
  gather_planes(pb, vb, walk, qb);

  SoftDepth soft(b.pos);
  add_side(a, va, b, qb, -1.0, soft);
  add_side(b, vb, a, qa, 1.0, soft);
  // No vertex inside the other (edge across edge), or D below PD: the point
  // contact of the penetration depth stays.
  soft.finish(r, r.depth, n);
}

}  // namespace grainlab
