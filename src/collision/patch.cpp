// Contact point and patch spread of two touching polytopes (see narrowphase.h).
//
// GJK/EPA (and the warm translated GJK) give a pair of witness points, which
// for two flat faces in contact is an arbitrary point of the common patch that
// jumps from step to step. Here the point is instead a weighted centroid of
// the vertices of each body that lie inside the other, each weighted by how
// deep it lies inside the other body: w(x) = min(height beyond the other's
// supporting plane, min over the other's nearby face planes of the depth
// below the plane). That weight is the (clamped) signed distance of x inside
// the other polytope, continuous in the configuration and zero when x enters
// or leaves the overlap, so the point moves continuously (unlike choosing a
// "feature" by a tolerance band, which switches between a vertex and a face).
//
// Nearby face planes: the faces incident to the other body's vertices beyond
// this body's supporting plane. Every face of B lying under a vertex x of A
// that is inside B (height of x at most A's top) has such a vertex, so the
// set holds the face below x and the side faces next to it.
#include "collision/narrowphase.h"

#include <cstdint>
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

struct Accum {
  Vec3 ref, n;  // reference point, contact normal
  Vec3 sum = Vec3::Zero();
  double sq = 0, tot = 0;
  void add(const Vec3& x, double w) {
    const Vec3 d = x - ref;
    sum += w * d;
    sq += w * (d - d.dot(n) * n).squaredNorm();  // tangential
    tot += w;
  }
};

// Adds the vertices `verts` of `s` (excess over the other body's supporting
// plane: base + dot(v, dir)) weighted by their depth inside `o`.
void add_side(const PolytopeShape& s, const std::vector<Index>& verts, const Vec3& dir, double base,
              const PolytopeShape& o, const std::vector<Index>& o_planes, Accum& acc) {
  const ConvexPolytope& poly = *s.poly;
  const auto& planes = o.poly->planes();
  const Mat3 to_o = o.rot.transpose() * s.rot * (s.scale / o.scale);  // local s -> local o
  const Vec3 off = o.rot.transpose() * (s.pos - o.pos) / o.scale;
  for (const Index v : verts) {
    const Vec3& pv = poly.vertex(v);
    double w = base + pv.dot(dir);  // world units
    const Vec3 xl = to_o * pv + off;
    for (const Index k : o_planes) w = std::min(w, (planes[k].c - planes[k].m.dot(xl)) * o.scale);
    if (w > 0) acc.add(s.pos + s.scale * (s.rot * pv), w);
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

  thread_local Walk walk;
  thread_local std::vector<Index> va, vb, qa, qb;
  if (!collect(pa, sa, nla, ha0 - bot_b, walk, va)) return;
  if (!collect(pb, sb, -nlb, top_a - hb0, walk, vb)) return;
  gather_planes(pa, va, walk, qa);
  gather_planes(pb, vb, walk, qb);

  Accum acc{r.point, n};
  add_side(a, va, nla, ha0 - bot_b, b, qb, acc);
  add_side(b, vb, -nlb, top_a - hb0, a, qa, acc);
  if (!(acc.tot > 0)) return;  // no vertex inside the other: keep the witness point
  // A whisker of the witness point keeps the result defined as the weights vanish.
  const double w0 = 1e-9 * r.depth;
  const Vec3 mean = acc.sum / (acc.tot + w0);
  Vec3 c = r.point + mean;
  // Spread in the contact plane: tangential weighted variance.
  const Vec3 mean_t = mean - mean.dot(n) * n;
  r.spread = std::max(0.0, acc.sq / (acc.tot + w0) - mean_t.squaredNorm());
  // Halfway between the two supporting planes.
  c += (0.5 * (top_a + bot_b) - n.dot(c)) * n;
  r.point = c;
}

}  // namespace grainlab
