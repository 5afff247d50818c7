// The contact of two touching polytopes (see narrowphase.h): the soft depth
// of soft_depth.h over the parts of each body's edges lying inside the other.
//
// A point x of A is inside B iff it is below every face plane of B; its
// depth is its distance inside B's nearest face plane (for a point inside a
// convex body, the distance to its boundary), a continuous function of the
// two poses, zero where x enters. Only faces near the contact are tried: the
// faces through B's vertices below A's supporting plane (along the point
// contact's normal n). B above that plane lies in a half space that A's
// points do not enter, and B's part below it is bounded by exactly those
// faces, so a point of A is inside B iff it is below them all. Only edges
// that can reach into B are tried: those at A's vertices above B's
// supporting plane (an edge with a point inside B has an end there).
//
// GJK/EPA (or the warm translated GJK) still tells whether the pair touches
// and gives the normal the force is checked against; the potential is u(D)
// alone.
#include "collision/narrowphase.h"
#include "collision/soft_depth.h"

#include <cstdint>
#include <algorithm>
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

// Per-thread scratch of add_edges: o's candidate planes, and each visited
// vertex's row of distances inside them (o's local units), computed once per
// vertex.
struct EdgeScratch {
  std::vector<ConvexPolytope::Plane> plane;
  std::vector<double> dist;
  std::vector<std::uint32_t> violated;  // the planes one vertex is outside of
  std::vector<std::uint32_t> row_of;  // per vertex: its row, valid where stamped
  // One edge's candidate lines: depth at its start (o's local units), slope
  // per unit t, plane.
  std::vector<double> l0, slope;
  std::vector<std::uint32_t> line_plane;
  Walk rows, member;
};

// Adds the parts of the edges of `s` at the vertices `verts` that lie inside
// `o` to the soft depth: along an edge x(t) = p + t (q - p), t in [0, 1], the
// depth inside o is the lower envelope of the plane distances
// l_k(t) = c_k - m_k . x(t) over `o_planes` (o's faces that can bound the
// overlap), piecewise linear; each piece enters the soft depth
// (add_linear_piece) pushed out along its plane's normal. `sign` is +1 if
// s is B (the push on B), -1 if s is A (the reaction on B). `x.member`
// marks `verts` (so an edge between two of them is taken once).
void add_edges(const PolytopeShape& s, const std::vector<Index>& verts, const PolytopeShape& o,
               const std::vector<Index>& o_planes, double sign, EdgeScratch& x, SoftDepth& soft) {
  const ConvexPolytope& poly = *s.poly;
  const std::size_t np = o_planes.size();
  if (np == 0) return;
  x.plane.resize(np);
  x.l0.resize(np), x.slope.resize(np), x.line_plane.resize(np);
  for (std::size_t k = 0; k < np; ++k) x.plane[k] = o.poly->planes()[o_planes[k]];
  if (x.row_of.size() < poly.size()) x.row_of.resize(poly.size());
  x.rows.begin(poly.size());
  x.dist.clear();
  const Mat3 to_o = o.rot.transpose() * s.rot * (s.scale / o.scale);  // local s -> local o
  const Vec3 off = o.rot.transpose() * (s.pos - o.pos) / o.scale;
  const auto row = [&](Index v, const Vec3& pl) -> std::size_t {  // v's row (dist may grow: an offset)
    if (!x.rows.mark(v)) return x.row_of[v];
    const std::size_t r = x.dist.size();
    x.dist.resize(r + np);
    double* d = x.dist.data() + r;
    for (std::size_t k = 0; k < np; ++k) d[k] = x.plane[k].c - x.plane[k].m.dot(pl);
    x.row_of[v] = static_cast<std::uint32_t>(r);
    return r;
  };
  x.member.begin(poly.size());
  for (const Index v : verts) x.member.mark(v);
  for (const Index v : verts) {
    const std::size_t rv = row(v, to_o * poly.vertex(v) + off);
    // The planes v is outside of: an edge from v is outside o if its other
    // end is outside one of them too (the test of a plane with both ends
    // outside, at one dot product per plane for w).
    x.violated.clear();
    for (std::size_t k = 0; k < np; ++k)
      if (x.dist[rv + k] <= 0) x.violated.push_back(static_cast<std::uint32_t>(k));
    for (const Index* it = poly.neighbours_begin(v); it != poly.neighbours_end(v); ++it) {
      const Index w = *it;
      if (x.member.stamp[w] == x.member.generation && w < v) continue;  // taken from w's side
      if (!poly.is_edge(it)) continue;
      const Vec3 wl = to_o * poly.vertex(w) + off;
      bool outside = false;
      for (const std::uint32_t k : x.violated)
        if (x.plane[k].c - x.plane[k].m.dot(wl) <= 0) {
          outside = true;
          break;
        }
      if (outside) continue;
      const std::size_t rw = row(w, wl);
      const double* dp = x.dist.data() + rv;
      const double* dq = x.dist.data() + rw;
      // Every line l_k lies below max(dp[k], dq[k]) on the edge, so the
      // envelope lies below U = min_k max(dp[k], dq[k]): if U <= 0 the edge is
      // outside o (one plane has both ends outside), and only lines that dip
      // below U somewhere (min(dp[k], dq[k]) <= U) can be on the envelope.
      double upper = std::max(dp[0], dq[0]);
      for (std::size_t k = 1; k < np; ++k) upper = std::min(upper, std::max(dp[k], dq[k]));
      if (upper <= 0) continue;
      // The lines that dip below U, compacted without branches: value at
      // t = 0 and slope along the edge, and their plane.
      double* const l0 = x.l0.data();
      double* const sl = x.slope.data();
      std::uint32_t* const pl = x.line_plane.data();
      std::size_t n = 0;
      for (std::size_t k = 0; k < np; ++k) {
        l0[n] = dp[k], sl[n] = dq[k] - dp[k], pl[n] = static_cast<std::uint32_t>(k);
        n += std::min(dp[k], dq[k]) <= upper;
      }
      // Lower envelope of those lines: from t = 0, the lowest line there
      // (ties: the one falling fastest), up to the first line crossing below
      // it, which continues it (ties: again the one falling fastest), and so on.
      std::size_t cur = 0;
      for (std::size_t j = 1; j < n; ++j)
        if (l0[j] < l0[cur] || (l0[j] == l0[cur] && sl[j] < sl[cur])) cur = j;
      const Vec3 p = s.pos + s.scale * (s.rot * poly.vertex(v));
      const Vec3 e = s.scale * (s.rot * (poly.vertex(w) - poly.vertex(v)));
      double t0 = 0;
      while (t0 < 1) {
        const double slope = sl[cur], lc = l0[cur];
        if (lc + slope * t0 <= 0 && slope <= 0) break;  // the envelope is concave: outside from here on
        double t1 = 1;
        std::size_t next = cur;
        for (std::size_t j = 0; j < n; ++j) {
          const double sk = sl[j];
          if (!(sk < slope)) continue;
          // Line j meets the current one at tc = (l0[j] - lc) / (slope - sk)
          // (slope - sk > 0): divide only when it can be the next crossing.
          const double num = l0[j] - lc, den = slope - sk;
          if (!(num < (t1 + 1e-12) * den)) continue;
          const double tc = num / den;
          if (!(tc > t0)) continue;
          // The earliest crossing; of crossings equally early within rounding
          // the line falling fastest. Slopes fall at every switch: at most np.
          const bool earlier = tc < t1 - 1e-12;
          const bool tied = !earlier && tc <= t1 + 1e-12 && next != cur && sk < sl[next];
          if (earlier || tied) t1 = std::min(t1, tc), next = j;
        }
        soft.add_linear_piece(p + t0 * e, p + t1 * e, (lc + slope * t0) * o.scale, (lc + slope * t1) * o.scale,
                              sign * (o.rot * x.plane[pl[cur]].m));
        if (next == cur) break;
        cur = next;
        t0 = t1;
      }
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
  thread_local EdgeScratch scratch;
  add_edges(a, va, b, qb, -1.0, scratch, soft);
  add_edges(b, vb, a, qa, 1.0, scratch, soft);
  // Nothing inside (an overlap too thin to resolve) or a force against the
  // normal (soft_depth.h): the point contact of the penetration depth stays.
  soft.finish(r, n);
}

}  // namespace grainlab
