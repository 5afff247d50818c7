// The shape-pair table and its one registration block.
//
// Flipped use of a routine registered for (B, A) on a pair (A, B): the shapes
// and the cache's two hints are swapped and its direction negated (the cache
// stores them for a to b), the routine runs, the cache is swapped back and
// every result normal negated. Negation is exact, so the flipped call gives
// the bits the direct routine would give for (B, A).
#include "collision/dispatch.h"

#include "collision/pair_routines.h"

#include <array>
#include <stdexcept>
#include <string>
#include <utility>

namespace grainlab {

namespace {

struct Entry {
  PairRoutine fn = nullptr;
  bool flip = false;  // fn is registered for (b, a)
};

using Table = std::array<std::array<Entry, kShapeKindCount>, kShapeKindCount>;

constexpr int idx(ShapeKind k) { return static_cast<int>(k); }

constexpr Table make_table() {
  Table t{};
  const auto reg = [&t](ShapeKind a, ShapeKind b, PairRoutine f) {
    t[idx(a)][idx(b)] = {f, false};
    if (!t[idx(b)][idx(a)].fn) t[idx(b)][idx(a)] = {f, a != b};
  };
  // --- the registration block: one line per routine ---
  using K = ShapeKind;
  reg(K::Sphere, K::Sphere, routines::sphere_sphere);
  reg(K::Sphere, K::Polytope, routines::sphere_polytope);
  reg(K::Polytope, K::Polytope, routines::polytope_polytope);
  reg(K::Plane, K::Sphere, routines::plane_sphere);
  reg(K::Plane, K::Polytope, routines::plane_polytope);
  reg(K::Box, K::Sphere, routines::box_sphere);
  reg(K::Box, K::Polytope, routines::box_polytope);
  reg(K::Sphere, K::Compound, routines::any_compound);
  reg(K::Polytope, K::Compound, routines::any_compound);
  reg(K::Plane, K::Compound, routines::any_compound);
  reg(K::Box, K::Compound, routines::any_compound);
  reg(K::Compound, K::Compound, routines::compound_compound);
  return t;
}

constexpr Table kTable = make_table();

}  // namespace

bool has_pair_routine(ShapeKind a, ShapeKind b) { return kTable[idx(a)][idx(b)].fn != nullptr; }

namespace {

// The cache of the pair taken the other way round (b to a).
PairCache flipped(const PairCache& c) { return {-c.dir, c.hint_b, c.hint_a, c.warm, c.simplex.swapped()}; }

}  // namespace

int piece_cache_count(const PosedShape& a, const PosedShape& b) {
  const auto pieces = [](const PosedShape& s) {
    return s.kind == ShapeKind::Compound ? static_cast<int>(s.compound->pieces.size()) : 1;
  };
  return a.kind == ShapeKind::Compound || b.kind == ShapeKind::Compound ? pieces(a) * pieces(b) : 0;
}

int collide_shapes(const PosedShape& a, const PosedShape& b, PairCache& cache, SubContact* out, PairCache* pieces) {
  const Entry& e = kTable[idx(a.kind)][idx(b.kind)];
  if (!e.fn) [[unlikely]]
    throw std::logic_error("no narrowphase routine for shape kinds " + std::to_string(idx(a.kind)) + " and " +
                           std::to_string(idx(b.kind)));
  if (!e.flip) return e.fn(a, b, cache, pieces, out);
  // Flipped: a convex shape against a compound's pieces (at most
  // kMaxCompoundPieces piece caches, each flipped like the pair's).
  PairCache flipped_pieces[kMaxCompoundPieces];
  const int np = pieces ? piece_cache_count(a, b) : 0;
  for (int k = 0; k < np; ++k) flipped_pieces[k] = flipped(pieces[k]);
  PairCache f = flipped(cache);
  const int n = e.fn(b, a, f, pieces ? flipped_pieces : nullptr, out);
  cache = flipped(f);
  for (int k = 0; k < np; ++k) pieces[k] = flipped(flipped_pieces[k]);
  for (int k = 0; k < n; ++k) out[k].geo.normal = -out[k].geo.normal;
  return n;
}

}  // namespace grainlab
