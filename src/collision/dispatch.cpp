// The shape-pair table and its one registration block.
//
// Flipped use of a routine registered for (B, A) on a pair (A, B): the shapes
// and the cache's two hints are swapped and its direction negated (the cache
// stores them for a to b), the routine runs, the cache is swapped back and
// every result normal negated. Negation is exact, so the flipped call gives
// the bits the direct routine would give for (B, A).
#include "collision/dispatch.h"

#include "collision/compound.h"
#include "collision/pair_routines.h"

#include <array>
#include <mutex>
#include <stdexcept>
#include <string>
#include <utility>

namespace grainlab {

namespace {

struct Entry {
  PairRoutine fn = nullptr;
  bool flip = false;  // fn is registered for (b, a)
  PairNeeds needs{.sub_contacts = 0, .reads_cache = false};
};

using Table = std::array<std::array<Entry, kMaxShapeKinds>, kMaxShapeKinds>;

constexpr int idx(ShapeKind k) { return static_cast<int>(k); }

// Registers f for (a, b) and, unless (b, a) has one, flipped for (b, a).
constexpr void enter(Table& t, ShapeKind a, ShapeKind b, PairRoutine f, PairNeeds needs) {
  t[idx(a)][idx(b)] = {f, false, needs};
  if (!t[idx(b)][idx(a)].fn || t[idx(b)][idx(a)].flip) t[idx(b)][idx(a)] = {f, a != b, needs};
}

constexpr Table make_table() {
  Table t{};
  const auto reg = [&t](ShapeKind a, ShapeKind b, PairRoutine f, PairNeeds needs) { enter(t, a, b, f, needs); };
  // What the pairs need (PairNeeds): one result and the pair's cache...
  constexpr PairNeeds cached{};
  // ... one result from exact geometry, no cache ...
  constexpr PairNeeds exact{.reads_cache = false};
  // ... and of two spheres, the compact path too ...
  constexpr PairNeeds compact{.reads_cache = false, .compact = true};
  // ... or a compound's: a result and a cache per piece (pair).
  constexpr PairNeeds pieces{.sub_contacts = kMaxSubContacts, .extra_caches = routines::piece_pairs};
  // --- the registration block: one line per routine ---
  using K = ShapeKind;
  reg(K::Sphere, K::Sphere, routines::sphere_sphere, compact);
  reg(K::Sphere, K::Polytope, routines::sphere_polytope, cached);
  reg(K::Polytope, K::Polytope, routines::polytope_polytope, cached);
  reg(K::Plane, K::Sphere, routines::plane_sphere, exact);
  reg(K::Plane, K::Polytope, routines::plane_polytope, cached);
  reg(K::Box, K::Sphere, routines::box_sphere, exact);
  reg(K::Box, K::Polytope, routines::box_polytope, cached);
  for (K convex : {K::Sphere, K::Polytope, K::Plane, K::Box}) reg(convex, K::Compound, routines::any_compound, pieces);
  reg(K::Compound, K::Compound, routines::compound_compound, pieces);
  return t;
}

// The table: the built-in block, constant-initialised; register_pair_routine
// adds to it before any stepping.
constinit Table g_table = make_table();

constinit std::mutex g_kinds_mutex;  // guards the registration of kinds and routines
constinit int g_kind_count = kBuiltInShapeKinds;

// The kinds' names, by id (a function's static: a registration during static
// initialisation finds it built).
std::array<std::string, kMaxShapeKinds>& kind_names() {
  static std::array<std::string, kMaxShapeKinds> names{"sphere", "polytope", "plane", "box", "compound"};
  return names;
}

}  // namespace

bool has_pair_routine(ShapeKind a, ShapeKind b) { return g_table[idx(a)][idx(b)].fn != nullptr; }

const PairNeeds& pair_needs(ShapeKind a, ShapeKind b) { return g_table[idx(a)][idx(b)].needs; }

ShapeKind register_shape_kind(const std::string& name) {
  const std::lock_guard lock(g_kinds_mutex);
  if (g_kind_count == kMaxShapeKinds)
    throw std::length_error("shape kind '" + name + "': the shape-pair table holds " +
                            std::to_string(kMaxShapeKinds) + " kinds; raise kMaxShapeKinds (shape_kind.h)");
  kind_names()[static_cast<std::size_t>(g_kind_count)] = name;
  return static_cast<ShapeKind>(g_kind_count++);
}

void register_pair_routine(ShapeKind a, ShapeKind b, PairRoutine fn, PairNeeds needs) {
  const std::lock_guard lock(g_kinds_mutex);
  if (idx(a) >= g_kind_count || idx(b) >= g_kind_count || !fn)
    throw std::logic_error("register_pair_routine: kinds " + std::to_string(idx(a)) + " and " +
                           std::to_string(idx(b)) + " must be registered and the routine given");
  enter(g_table, a, b, fn, needs);
}

int shape_kind_count() {
  const std::lock_guard lock(g_kinds_mutex);
  return g_kind_count;
}

std::string shape_kind_name(ShapeKind k) {
  const std::lock_guard lock(g_kinds_mutex);
  return idx(k) < g_kind_count ? kind_names()[static_cast<std::size_t>(idx(k))] : "kind " + std::to_string(idx(k));
}

namespace {

// The cache of the pair taken the other way round (b to a).
PairCache flipped(const PairCache& c) { return {-c.dir, c.hint_b, c.hint_a, c.warm, c.simplex.swapped()}; }

}  // namespace

int piece_cache_count(const PosedShape& a, const PosedShape& b) {
  const Entry& e = g_table[idx(a.kind)][idx(b.kind)];
  if (!e.needs.extra_caches) return 0;
  return e.flip ? e.needs.extra_caches(b, a) : e.needs.extra_caches(a, b);
}

int collide_shapes(const PosedShape& a, const PosedShape& b, PairCache& cache, SubContact* out, PairCache* pieces) {
  const Entry& e = g_table[idx(a.kind)][idx(b.kind)];
  if (!e.fn) [[unlikely]]
    throw std::logic_error("no narrowphase routine for shape kinds " + shape_kind_name(a.kind) + " and " +
                           shape_kind_name(b.kind) + " (register one: dispatch.h)");
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
