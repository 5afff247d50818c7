// Pair routines of compound shapes (compound.h): each piece is posed as a
// convex shape of its own and collided through the table (dispatch.h) with a
// cold cache whose direction is the line between the two centres; only
// touching piece contacts are written, in increasing sub-contact id.
#include "collision/dispatch.h"
#include "collision/pair_routines.h"

namespace grainlab::routines {

namespace {

PosedShape pose_piece(const PosedShape& c, const CompoundPiece& p) {
  PosedShape s;
  s.kind = p.kind;
  s.hull = &p.hull;
  s.radius = p.radius * c.scale;
  s.rot = c.rot;
  s.q = c.q;
  s.pos = c.pos + *c.rot * (c.scale * p.offset);
  s.scale = c.scale;
  return s;
}

// Collides two convex shapes with a cold cache; appends a touching result with id `sub`.
void collide_piece(const PosedShape& a, const PosedShape& b, std::int32_t sub, SubContact* out, int& n) {
  PairCache cache;
  const Vec3 d = b.pos - a.pos;
  if (d.squaredNorm() > 0) cache.dir = d;
  SubContact r[kMaxSubContacts];
  const int m = collide_shapes(a, b, cache, r);
  for (int k = 0; k < m && n < kMaxSubContacts; ++k)
    if (r[k].geo.touching) out[n++] = {r[k].geo, sub};
}

}  // namespace

int any_compound(const PosedShape& a, const PosedShape& b, PairCache&, SubContact* out) {
  int n = 0;
  const auto& pieces = b.compound->pieces;
  for (std::size_t j = 0; j < pieces.size(); ++j)
    collide_piece(a, pose_piece(b, pieces[j]), static_cast<std::int32_t>(j), out, n);
  return n;
}

int compound_compound(const PosedShape& a, const PosedShape& b, PairCache&, SubContact* out) {
  int n = 0;
  const auto& pa = a.compound->pieces;
  const auto& pb = b.compound->pieces;
  for (std::size_t i = 0; i < pa.size(); ++i) {
    const PosedShape ai = pose_piece(a, pa[i]);
    for (std::size_t j = 0; j < pb.size(); ++j)
      collide_piece(ai, pose_piece(b, pb[j]), static_cast<std::int32_t>(i * pb.size() + j), out, n);
  }
  return n;
}

}  // namespace grainlab::routines
