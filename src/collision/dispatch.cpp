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

int collide_shapes(const PosedShape& a, const PosedShape& b, PairCache& cache, SubContact* out) {
  const Entry& e = kTable[idx(a.kind)][idx(b.kind)];
  if (!e.fn) [[unlikely]]
    throw std::logic_error("no narrowphase routine for shape kinds " + std::to_string(idx(a.kind)) + " and " +
                           std::to_string(idx(b.kind)));
  if (!e.flip) return e.fn(a, b, cache, out);
  PairCache flipped{-cache.dir, cache.hint_b, cache.hint_a, cache.warm, cache.simplex.swapped()};
  const int n = e.fn(b, a, flipped, out);
  cache = {-flipped.dir, flipped.hint_b, flipped.hint_a, flipped.warm, flipped.simplex.swapped()};
  for (int k = 0; k < n; ++k) out[k].geo.normal = -out[k].geo.normal;
  return n;
}

}  // namespace grainlab
