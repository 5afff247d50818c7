// Pair routines of compound shapes (compound.h): each piece is posed as a
// convex shape of its own and collided through the table (dispatch.h) with
// the piece pair's own cache, kept between steps as a convex pair's is (its
// last normal, support hints and GJK simplex: simplex_cache.h), or, when the
// caller keeps none, a cold cache whose direction is the line between the
// two centres; a piece pair skipped (apart, or separated along the pair's
// direction) starts its next collision cold from that line, as a convex
// pair whose bounding spheres part does. Only touching piece contacts are
// written, in increasing sub-contact id.
// Pieces whose bounding spheres are apart are skipped. A contact is kept
// only if its point lies in the cell of each piece it belongs to (compound.h),
// widened by its depth: the point lies within half the depth of the piece, so
// a piece's own contacts are never dropped, and of two pieces meeting a
// neighbour across their common cut, only the one whose cell holds the
// contact point keeps it (both only within the depth of the cut).
// That leaves the corner of the other piece: a neighbour pressing a face near
// a cut also meets the edge where the cut ends that face, with a smaller
// depth and a normal tilted towards the cut (measured on a U grain's flat
// underside: 1.5 times the force within the contact radius of the cut).
// (Ownership is a hard test; with the depth as slack it did not keep a
// specimen from resting, see docs/grains.md.)
// So contacts of one pair whose normals and points are close are one contact
// across a seam and share its force (weigh_seams below). Contacts of a dent
// or a hook face different ways (the trough's floor and wall: 90 degrees)
// and keep all of theirs.
// A piece pair is also skipped when a plane perpendicular to the pair's
// direction n separates the two pieces: the largest n.x over piece i of A is
// below the smallest over piece j of B (exact for any n; n is the pair's
// deepest normal from the last step, kept in its PairCache, else the line
// between the centres). Skipping only separated pairs changes no contact.
#include "collision/compound.h"
#include "collision/dispatch.h"
#include "collision/pair_routines.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace grainlab::routines {

namespace {

PosedShape pose_piece(const PosedShape& c, const CompoundPiece& p) {
  PosedShape s;
  s.kind = p.kind;
  s.geometry = &p.hull;  // a sphere piece reads none
  s.radius = p.radius * c.scale;
  s.rot = c.rot;
  s.q = c.q;
  s.pos = c.pos + *c.rot * (c.scale * p.offset);
  s.scale = c.scale;
  return s;
}

// World radius of a posed piece's bounding sphere about its origin.
double piece_bound(const PosedShape& c, const CompoundPiece& p) {
  return c.scale * (p.kind == ShapeKind::Sphere ? p.radius : p.hull.bounding_radius());
}

// World radius of a posed compound's bounding sphere about its origin.
double compound_bound(const PosedShape& c) {
  double r = 0;
  for (const CompoundPiece& p : c.geometry_as<CompoundShape>().pieces) r = std::max(r, c.scale * p.offset.norm() + piece_bound(c, p));
  return r;
}

// Bounding radius of a convex posed shape about pos; infinite for walls.
double shape_bound(const PosedShape& s) {
  if (s.kind == ShapeKind::Sphere) return s.radius;
  if (s.kind == ShapeKind::Polytope) return s.geometry_as<ConvexPolytope>().bounding_radius() * s.scale;
  return std::numeric_limits<double>::infinity();
}

// max over the posed shape of d.x; +infinity for walls (no bound).
double support_value(const PosedShape& s, const Vec3& d) {
  if (s.kind == ShapeKind::Sphere) return d.dot(s.pos) + s.radius;
  if (s.kind == ShapeKind::Polytope) {
    const Vec3 local = s.rot->transpose() * d;
    const ConvexPolytope& hull = s.geometry_as<ConvexPolytope>();
    return d.dot(s.pos) + s.scale * local.dot(hull.vertex(hull.support_index(local, 0)));
  }
  return std::numeric_limits<double>::infinity();
}

// The direction to test separating planes along: the last deepest normal, else the centre line.
Vec3 pair_direction(const PosedShape& a, const PosedShape& b, const PairCache& cache) {
  if (cache.warm) return cache.dir;
  const Vec3 d = b.pos - a.pos;
  return d.squaredNorm() > 0 ? Vec3(d.normalized()) : Vec3::UnitZ();
}

// Keeps the deepest contact's normal for the next step's pair direction.
void remember_direction(PairCache& cache, const SubContact* out, int n) {
  cache.warm = n > 0;
  for (int k = 0; k < n; ++k)
    if (k == 0 || out[k].geo.depth > out[0].geo.depth) cache.dir = out[k].geo.normal;
}

bool apart(const PosedShape& a, double ra, const PosedShape& b, double rb) {
  return std::isfinite(ra) && std::isfinite(rb) && (b.pos - a.pos).squaredNorm() > (ra + rb) * (ra + rb);
}

// True if `point` (world) lies in the piece's cell, widened by `slack` (m).
bool owns(const PosedShape& c, const CompoundPiece& p, const Vec3& point, double slack) {
  if (p.cell.empty()) return true;
  const Vec3 local = c.rot->transpose() * (point - c.pos) / c.scale;
  for (const CellPlane& h : p.cell)
    if (h.n.dot(local) > h.c + slack / c.scale) return false;
  return true;
}

// Collides two convex shapes with `kept` (the piece pair's cache; null:
// cold); appends each touching result that `keep` accepts, with id `sub`.
// `size[k]` is the world bounding radius of the piece(s) of out[k].
template <class Keep>
void collide_piece(const PosedShape& a, const PosedShape& b, std::int32_t sub, double piece_size, PairCache* kept,
                   SubContact* out, double* size, int& n, Keep keep) {
  PairCache cold;
  PairCache& cache = kept ? *kept : cold;
  if (!cache.warm) {
    const Vec3 d = b.pos - a.pos;
    cache.dir = d.squaredNorm() > 0 ? d : Vec3(Vec3::UnitX());
  }
  SubContact r[kMaxSubContacts];
  const int m = collide_shapes(a, b, cache, r);
  for (int k = 0; k < m && n < kMaxSubContacts; ++k)
    if (r[k].geo.touching && keep(r[k].geo)) {
      size[n] = piece_size;
      out[n++] = {r[k].geo, sub};
    }
}

constexpr double kSeamCos = 0.940;   // cos(kSeamAngle), kSeamAngle = 20 degrees
constexpr double kSeamCos2 = 0.766;  // cos(2 kSeamAngle)
constexpr double kSeamReach = 0.25;

double smoothstep(double t) {
  t = std::clamp(t, 0.0, 1.0);
  return t * t * (3 - 2 * t);
}

// Shares the elastic force of contacts across a seam (above): contact i
// keeps the weight w_i = d_i^4 / (d_i^4 + sum_j s_ij d_j^4) of its force
// (its gain and twist), where s_ij in [0, 1] says how much i and j are one
// contact: 1 for normals within kSeamAngle and points within kSeamReach / 2
// of the smaller piece's size, 0 beyond twice the angle or beyond the reach,
// smooth in between. So two equal contacts at a seam give one contact's
// force, a shallow corner contact next to a deep face contact fades out
// (the total within 7 % of the deep one's alone for a Hertz force; 8.5 %
// measured with the soft depth of a U grain's flat underside), a
// contact that faces another way keeps all of its force, and every weight
// is continuous in the poses: a hard choice of the deepest flips from step
// to step and kept a consolidating specimen from coming to rest.
// The weight is also the result's `share`, with which the law scales its
// damping and tangential spring: with the elastic force alone shared, n
// results along a seam gave the contact n times one contact's damping and
// tangential stiffness (a sphere moving across the U grain's seams felt up
// to 1.52 times the hull's force, tests/dynamics/concave_contact_test.cpp).
void weigh_seams(SubContact* out, const double* size, int n) {
  double d4[kMaxSubContacts], sum[kMaxSubContacts];
  for (int i = 0; i < n; ++i) {
    const double d2 = out[i].geo.depth * out[i].geo.depth;
    d4[i] = d2 * d2;
    sum[i] = d4[i];
  }
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) {
      const ContactResult &p = out[i].geo, &q = out[j].geo;
      const double angle = smoothstep((p.normal.dot(q.normal) - kSeamCos2) / (kSeamCos - kSeamCos2));
      if (angle == 0) continue;
      const double reach = kSeamReach * std::min(size[i], size[j]);
      const double s = angle * (1 - smoothstep(2 * (p.point - q.point).norm() / reach - 1));
      sum[i] += s * d4[j];
      sum[j] += s * d4[i];
    }
  for (int i = 0; i < n; ++i) {
    const double w = sum[i] > 0 ? d4[i] / sum[i] : 1;
    out[i].geo.gain *= w;
    out[i].geo.twist *= w;
    out[i].geo.share = w;
  }
}

// The piece pair's cache is left to start cold next time (see the top).
void skipped(PairCache* pieces, std::size_t k) {
  if (pieces) pieces[k].warm = false;
}

}  // namespace

int piece_pairs(const PosedShape& a, const PosedShape& b) {
  const auto pieces = [](const PosedShape& s) {
    return s.kind == ShapeKind::Compound ? static_cast<int>(s.geometry_as<CompoundShape>().pieces.size()) : 1;
  };
  return pieces(a) * pieces(b);
}

int any_compound(const PosedShape& a, const PosedShape& b, PairCache& cache, PairCache* pieces, SubContact* out) {
  int n = 0;
  double size[kMaxSubContacts];
  const auto& pb = b.geometry_as<CompoundShape>().pieces;
  const double ra = shape_bound(a);
  const Vec3 dir = pair_direction(a, b, cache);
  const double top_a = support_value(a, dir);
  for (std::size_t j = 0; j < pb.size(); ++j) {
    const PosedShape bj = pose_piece(b, pb[j]);
    // Apart, or a plane along dir separates them.
    if (apart(a, ra, bj, piece_bound(b, pb[j])) || top_a < -support_value(bj, -dir)) {
      skipped(pieces, j);
      continue;
    }
    collide_piece(a, bj, static_cast<std::int32_t>(j), piece_bound(b, pb[j]), pieces ? pieces + j : nullptr, out, size,
                  n, [&](const ContactResult& r) { return owns(b, pb[j], r.point, r.depth); });
  }
  weigh_seams(out, size, n);
  remember_direction(cache, out, n);
  return n;
}

int compound_compound(const PosedShape& a, const PosedShape& b, PairCache& cache, PairCache* pieces,
                      SubContact* out) {
  int n = 0;
  double size[kMaxSubContacts];
  const auto& pa = a.geometry_as<CompoundShape>().pieces;
  const auto& pb = b.geometry_as<CompoundShape>().pieces;
  const double rb = compound_bound(b);
  const Vec3 dir = pair_direction(a, b, cache);
  // The lowest point of each piece of B along dir, and the highest of each
  // piece of A: support queries, found when a piece pair's bounding spheres
  // first overlap (the cheaper test first; a pair is skipped when either
  // says so, as before).
  constexpr double kNotYet = std::numeric_limits<double>::quiet_NaN();
  double low_b[kMaxCompoundPieces];
  std::fill_n(low_b, pb.size(), kNotYet);
  for (std::size_t i = 0; i < pa.size(); ++i) {
    const PosedShape ai = pose_piece(a, pa[i]);
    const double rai = piece_bound(a, pa[i]);
    if (apart(ai, rai, b, rb)) {
      for (std::size_t j = 0; j < pb.size(); ++j) skipped(pieces, i * pb.size() + j);
      continue;
    }
    double top_ai = kNotYet;
    for (std::size_t j = 0; j < pb.size(); ++j) {
      const std::size_t k = i * pb.size() + j;
      const PosedShape bj = pose_piece(b, pb[j]);
      if (apart(ai, rai, bj, piece_bound(b, pb[j]))) {
        skipped(pieces, k);
        continue;
      }
      if (std::isnan(top_ai)) top_ai = support_value(ai, dir);
      if (std::isnan(low_b[j])) low_b[j] = -support_value(bj, -dir);
      if (top_ai < low_b[j]) {  // a plane along dir separates them
        skipped(pieces, k);
        continue;
      }
      collide_piece(ai, bj, static_cast<std::int32_t>(k), std::min(rai, piece_bound(b, pb[j])),
                    pieces ? pieces + k : nullptr, out, size, n, [&](const ContactResult& r) {
                      return owns(a, pa[i], r.point, r.depth) && owns(b, pb[j], r.point, r.depth);
                    });
    }
  }
  weigh_seams(out, size, n);
  remember_direction(cache, out, n);
  return n;
}

}  // namespace grainlab::routines
