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

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
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

// Four doubles at a time (GCC/Clang vector extension: AVX on x86-64-v3),
// and the result of comparing them (all ones where true).
using Lanes = double __attribute__((vector_size(32)));
using Mask = long long __attribute__((vector_size(32)));
Lanes lanes(double v) { return Lanes{v, v, v, v}; }
// Four doubles from p, which need not be 32-byte aligned (memcpy: no alignment
// or aliasing assumed; a cast pointer with aligned(8) is honoured by GCC but
// read as an aligned load by Clang, which faulted).
Lanes load(const double* p) {
  Lanes v;
  std::memcpy(&v, p, sizeof v);
  return v;
}

// Per-thread scratch of add_edges: o's candidate planes as arrays (padded to
// whole lanes with planes no point is outside of), each vertex's row of
// distances inside them (o's local units) once it is needed, and each
// vertex's class: a plane it is outside of, or inside them all.
struct EdgeScratch {
  static constexpr std::size_t kLanes = 4;
  std::vector<double> mx, my, mz, c;  // plane k: distance c[k] - m[k] . x
  // The rows of this call: the first `used` entries of `dist`, which only
  // grows (no zero fill of each row before plane_distances writes it).
  std::vector<double> dist;
  std::size_t used = 0;
  std::vector<std::uint32_t> row_of;  // per vertex: its row, valid where stamped in `rows`
  std::vector<std::int32_t> outside;  // per vertex: a plane it is outside of, or -1; valid where stamped in `classes`
  // One edge's candidate lines: depth at its start (o's local units), slope
  // per unit t, plane.
  std::vector<double> l0, slope;
  std::vector<std::uint32_t> line_plane;
  Walk rows, classes, member;
};

// d[k] = c[k] - m[k] . p for the n planes (n whole lanes): the products of
// x and y added, then z's by a fused multiply-add, and contraction off so
// that the compiler fuses nothing else: the same rounding in the loop, which
// vectorizes (4 planes at a time on x86-64-v3), and in plane_distance below.
__attribute__((optimize("fp-contract=off"))) void plane_distances(const EdgeScratch& x, std::size_t n,
                                                                  const Vec3& p, double* d) {
  const double px = p.x(), py = p.y(), pz = p.z();
  const double *mx = x.mx.data(), *my = x.my.data(), *mz = x.mz.data(), *c = x.c.data();
  for (std::size_t k = 0; k < n; ++k) d[k] = c[k] - std::fma(mz[k], pz, mx[k] * px + my[k] * py);
}

// One plane's distance, rounded as above.
__attribute__((optimize("fp-contract=off"))) double plane_distance(const EdgeScratch& x, std::size_t k,
                                                                   const Vec3& p) {
  return x.c[k] - std::fma(x.mz[k], p.z(), x.mx[k] * p.x() + x.my[k] * p.y());
}

// Adds the parts of the edges of `s` at the vertices `verts` that lie inside
// `o` to the soft depth: along an edge x(t) = p + t (q - p), t in [0, 1], the
// depth inside o is the lower envelope of the plane distances
// l_k(t) = c_k - m_k . x(t) over `o_planes` (o's faces that can bound the
// overlap), piecewise linear; each piece enters the soft depth
// (add_linear_piece) pushed out along its plane's normal. `sign` is +1 if
// s is B (the push on B), -1 if s is A (the reaction on B). `x.member`
// marks `verts` (so an edge between two of them is taken once).
// Most of the vertices lie outside o (those of a flat face against a flat
// face: some 70 of a 1000-face angular grain's, 9 inside), so a vertex is
// first classed by one plane (the one its last classed neighbour was
// outside of) and gets its whole row only when that plane does not put it
// outside; an edge whose ends are outside one plane is skipped. What is
// skipped is what the envelope test (U <= 0 below) would skip.
void add_edges(const PolytopeShape& s, const std::vector<Index>& verts, const PolytopeShape& o,
               const std::vector<Index>& o_planes, double sign, EdgeScratch& x, SoftDepth& soft) {
  const ConvexPolytope& poly = *s.poly;
  const std::size_t np = o_planes.size();
  if (np == 0) return;
  const std::size_t npp = (np + EdgeScratch::kLanes - 1) / EdgeScratch::kLanes * EdgeScratch::kLanes;
  for (auto* a : {&x.mx, &x.my, &x.mz, &x.c}) a->resize(npp);
  for (std::size_t k = 0; k < npp; ++k) {
    const bool real = k < np;
    const ConvexPolytope::Plane& pl = o.poly->planes()[o_planes[real ? k : 0]];
    x.mx[k] = real ? pl.m.x() : 0, x.my[k] = real ? pl.m.y() : 0, x.mz[k] = real ? pl.m.z() : 0;
    x.c[k] = real ? pl.c : std::numeric_limits<double>::infinity();
  }
  x.l0.resize(npp), x.slope.resize(npp), x.line_plane.resize(npp);
  if (x.row_of.size() < poly.size()) x.row_of.resize(poly.size()), x.outside.resize(poly.size());
  x.rows.begin(poly.size());
  x.classes.begin(poly.size());
  x.used = 0;
  const Mat3 to_o = o.rot.transpose() * s.rot * (s.scale / o.scale);  // local s -> local o
  const Vec3 off = o.rot.transpose() * (s.pos - o.pos) / o.scale;
  const auto local = [&](Index v) -> Vec3 { return to_o * poly.vertex(v) + off; };
  const auto distance = [&](std::size_t k, const Vec3& pl) { return plane_distance(x, k, pl); };
  const auto row = [&](Index v, const Vec3& pl) -> std::size_t {  // v's row (dist may grow: an offset)
    if (!x.rows.mark(v)) return x.row_of[v];
    const std::size_t r = x.used;
    x.used = r + npp;
    if (x.used > x.dist.size()) x.dist.resize(std::max(2 * x.dist.size(), x.used));
    plane_distances(x, npp, pl, x.dist.data() + r);
    x.row_of[v] = static_cast<std::uint32_t>(r);
    return r;
  };
  std::int32_t hint = 0;  // the plane the last vertex classed was outside of
  const auto outside_plane = [&](Index v, const Vec3& pl) -> std::int32_t {  // a plane v is outside of, or -1
    if (!x.classes.mark(v)) return x.outside[v];
    std::int32_t k = -1;
    if (distance(hint, pl) <= 0) {
      k = hint;
    } else {
      const std::size_t r = row(v, pl);  // (before data(): the row may move dist)
      const double* d = x.dist.data() + r;
      for (std::size_t j = 0; j < np && k < 0; ++j)
        if (d[j] <= 0) k = static_cast<std::int32_t>(j);
      if (k >= 0) hint = k;
    }
    return x.outside[v] = k;
  };
  x.member.begin(poly.size());
  for (const Index v : verts) x.member.mark(v);
  for (const Index v : verts) {
    const Vec3 vl = local(v);
    const std::int32_t kv = outside_plane(v, vl);
    for (const Index* it = poly.neighbours_begin(v); it != poly.neighbours_end(v); ++it) {
      const Index w = *it;
      if (x.member.stamp[w] == x.member.generation && w < v) continue;  // taken from w's side
      if (!poly.is_edge(it)) continue;
      const Vec3 wl = local(w);
      // Both ends outside one plane: the edge is outside o.
      if (kv >= 0 && distance(kv, wl) <= 0) continue;
      const std::int32_t kw = outside_plane(w, wl);
      if (kw >= 0 && distance(kw, vl) <= 0) continue;
      const std::size_t rv = row(v, vl), rw = row(w, wl);
      const double* dp = x.dist.data() + rv;
      const double* dq = x.dist.data() + rw;
      // Which lines can be on the envelope E(t) = min_k l_k(t), 4 planes at a
      // time. Every line lies below max(dp[k], dq[k]) on the edge, so E lies
      // below U = min_k max(dp[k], dq[k]): if U <= 0 the edge is outside o
      // (one plane has both ends outside), and a line on E dips below U
      // somewhere (min(dp[k], dq[k]) <= U). And E lies below the line a lowest
      // at t = 0 and the line b lowest at t = 1, so a line on E at t has
      // l_k(t) <= l_a(t) and l_k(t) <= l_b(t): with f = l_k - l_a (f0 >= 0)
      // and g = l_k - l_b (g1 >= 0), f <= 0 on [f0 / (f0 - f1), 1] when
      // f1 <= 0, g <= 0 on [0, g0 / (g0 - g1)] when g0 <= 0, and the two
      // meet iff f0 (g1 - g0) + g0 (f0 - f1) <= 0. Among nearly coplanar
      // faces (a flat face of an angular grain) that keeps a few of some 30
      // lines below U. A slack of 1e-9 of the depths keeps the lines that
      // the walk below could take by its own tolerance.
      constexpr std::size_t L = EdgeScratch::kLanes;
      const std::size_t blocks = npp / L;
      Lanes e0 = load(dp), e1 = load(dq), u = e0 > e1 ? e0 : e1;
      for (std::size_t i = 1; i < blocks; ++i) {
        const Lanes p0 = load(dp + i * L), q0 = load(dq + i * L);
        const Lanes hi = p0 > q0 ? p0 : q0;
        u = hi < u ? hi : u;
        e0 = p0 < e0 ? p0 : e0;
        e1 = q0 < e1 ? q0 : e1;
      }
      const double upper = std::min(std::min(u[0], u[1]), std::min(u[2], u[3]));
      if (upper <= 0) continue;
      const double min0 = std::min(std::min(e0[0], e0[1]), std::min(e0[2], e0[3]));
      const double min1 = std::min(std::min(e1[0], e1[1]), std::min(e1[2], e1[3]));
      std::size_t a = 0, b = 0;
      while (dp[a] != min0) ++a;
      while (dq[b] != min1) ++b;
      const double slack = 1e-9 * std::max({std::abs(upper), std::abs(min0), std::abs(min1)});
      const Lanes pa = lanes(dp[a]), qa = lanes(dq[a]), pb = lanes(dp[b]), qb = lanes(dq[b]);
      const Lanes up = lanes(upper), tol = lanes(slack), tol2 = lanes(slack * slack);
      // The lines kept, compacted: value at t = 0 and slope along the edge, and their plane.
      double* const l0 = x.l0.data();
      double* const sl = x.slope.data();
      std::uint32_t* const pl = x.line_plane.data();
      std::size_t n = 0;
      for (std::size_t i = 0; i < blocks; ++i) {
        const Lanes p0 = load(dp + i * L), q0 = load(dq + i * L);
        const Lanes f0 = p0 - pa, f1 = q0 - qa, g0 = p0 - pb, g1 = q0 - qb;
        const Mask keep = ((p0 < q0 ? p0 : q0) <= up) & (f1 <= tol) & (g0 <= tol) &
                          (f0 * (g1 - g0) + g0 * (f0 - f1) <= tol2 + tol * (f0 - f1 + g1 - g0));
        if (!(keep[0] | keep[1] | keep[2] | keep[3])) continue;
        for (std::size_t j = 0; j < EdgeScratch::kLanes; ++j) {
          const std::size_t k = i * EdgeScratch::kLanes + j;
          l0[n] = dp[k], sl[n] = dq[k] - dp[k], pl[n] = static_cast<std::uint32_t>(k);
          n += keep[j] != 0;
        }
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
                              sign * (o.rot * o.poly->planes()[o_planes[pl[cur]]].m));
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
