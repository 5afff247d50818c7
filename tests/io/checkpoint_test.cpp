// Checkpoints: a State with random contents comes back bit for bit; damaged,
// truncated and wrong-version files are refused with a clear message.
#include "core/bytes.h"
#include "geometry/primitives.h"
#include "io/checkpoint.h"

#include "core/error.h"
#include "core/atomic_file.h"
#include "io/config.h"
#include "io_test_helpers.h"

#include <gtest/gtest.h>

#include <bit>
#include <fstream>
#include <random>

namespace grainlab {
namespace {

class RandomFill {
 public:
  explicit RandomFill(std::uint64_t seed) : rng_(seed) {}
  // Any bit pattern, NaNs included: the format must keep raw bits.
  double d() { return std::bit_cast<double>(bits_(rng_)); }
  Vec3 v() { return {d(), d(), d()}; }
  Quat q() { return Quat(d(), d(), d(), d()); }
  Index i() { return static_cast<Index>(bits_(rng_)); }
  bool b() { return bits_(rng_) & 1; }
  std::size_t n(std::size_t max) { return bits_(rng_) % (max + 1); }

  PairCache cache() {
    PairCache c;
    c.dir = v(), c.hint_a = i(), c.hint_b = i(), c.warm = b();
    c.simplex.n = static_cast<std::int32_t>(n(3));
    for (int k = 0; k < 3; ++k) c.simplex.a[k] = i(), c.simplex.b[k] = i();
    return c;
  }

  // A pair, with piece caches at `pieces` (or -1) of a pool of `pool` caches.
  CandidatePair pair(std::size_t pool) {
    CandidatePair p;
    p.a = i(), p.b = i(), p.cache = cache();
    p.pieces = pool > 0 && b() ? static_cast<std::int32_t>(n(pool - 1)) : -1;
    return p;
  }

  Contact contact() {
    Contact p;
    p.a = i(), p.b = i(), p.sub = i(), p.xi = v();
    p.geo.touching = b(), p.geo.depth = d(), p.geo.normal = v(), p.geo.point = v(), p.geo.spread = d();
    p.force = v(), p.torque = v(), p.normal_force = d();
    return p;
  }

  State state() {
    State s;
    s.time = d();
    s.step = static_cast<std::int64_t>(bits_(rng_));
    s.rebuild_pairs = b();
    s.bodies.resize(n(50) + 1);
    for (BodyState& x : s.bodies) x.x = v(), x.v = v(), x.w = v(), x.q = q();
    s.walls.resize(n(6) + 1);
    for (WallState& w : s.walls) w.x = v(), w.q = q(), w.v = v(), w.force = v();
    s.piece_caches.resize(n(100));
    for (PairCache& c : s.piece_caches) c = cache();
    s.wall_piece_caches.resize(n(20));
    for (PairCache& c : s.wall_piece_caches) c = cache();
    s.pairs.resize(n(80) + 1);
    for (CandidatePair& p : s.pairs) p = pair(s.piece_caches.size());
    s.wall_pairs.resize(n(30) + 1);
    for (CandidatePair& p : s.wall_pairs) p = pair(s.wall_piece_caches.size());
    s.contacts.resize(n(80) + 1);
    for (Contact& p : s.contacts) p = contact();
    s.wall_contacts.resize(n(30) + 1);
    for (Contact& p : s.wall_contacts) p = contact();
    s.x_at_rebuild.resize(s.bodies.size());
    for (Vec3& x : s.x_at_rebuild) x = v();
    s.wall_x_at_rebuild.resize(n(2) == 0 ? 0 : s.walls.size());  // kept (a world of spheres) or not
    s.wall_q_at_rebuild.resize(s.wall_x_at_rebuild.size());
    for (Vec3& x : s.wall_x_at_rebuild) x = v();
    for (Quat& wq : s.wall_q_at_rebuild) wq = q();
    return s;
  }

 private:
  std::mt19937_64 rng_;
  std::uniform_int_distribution<std::uint64_t> bits_;
};

std::uint64_t bits(double x) { return std::bit_cast<std::uint64_t>(x); }

void expect_same(const Vec3& a, const Vec3& b) {
  for (int k = 0; k < 3; ++k) EXPECT_EQ(bits(a[k]), bits(b[k]));
}
void expect_same(const Quat& a, const Quat& b) {
  for (int k = 0; k < 4; ++k) EXPECT_EQ(bits(a.coeffs()[k]), bits(b.coeffs()[k]));
}
void expect_same(const PairCache& a, const PairCache& b) {
  expect_same(a.dir, b.dir);
  EXPECT_EQ(a.hint_a, b.hint_a);
  EXPECT_EQ(a.hint_b, b.hint_b);
  EXPECT_EQ(a.warm, b.warm);
  EXPECT_EQ(a.simplex.n, b.simplex.n);
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(a.simplex.a[k], b.simplex.a[k]);
    EXPECT_EQ(a.simplex.b[k], b.simplex.b[k]);
  }
}
void expect_same(const CandidatePair& a, const CandidatePair& b) {
  EXPECT_EQ(a.a, b.a);
  EXPECT_EQ(a.b, b.b);
  expect_same(a.cache, b.cache);
  EXPECT_EQ(a.pieces, b.pieces);
}
void expect_same(const Contact& a, const Contact& b) {
  EXPECT_EQ(a.a, b.a);
  EXPECT_EQ(a.b, b.b);
  EXPECT_EQ(a.sub, b.sub);
  expect_same(a.xi, b.xi);
  EXPECT_EQ(a.geo.touching, b.geo.touching);
  EXPECT_EQ(bits(a.geo.depth), bits(b.geo.depth));
  expect_same(a.geo.normal, b.geo.normal);
  expect_same(a.geo.point, b.geo.point);
  EXPECT_EQ(bits(a.geo.spread), bits(b.geo.spread));
  expect_same(a.force, b.force);
  expect_same(a.torque, b.torque);
  EXPECT_EQ(bits(a.normal_force), bits(b.normal_force));
}
void expect_same(const State& a, const State& b) {
  EXPECT_EQ(bits(a.time), bits(b.time));
  EXPECT_EQ(a.step, b.step);
  EXPECT_EQ(a.rebuild_pairs, b.rebuild_pairs);
  ASSERT_EQ(a.bodies.size(), b.bodies.size());
  for (std::size_t i = 0; i < a.bodies.size(); ++i) {
    expect_same(a.bodies[i].x, b.bodies[i].x);
    expect_same(a.bodies[i].v, b.bodies[i].v);
    expect_same(a.bodies[i].w, b.bodies[i].w);
    expect_same(a.bodies[i].q, b.bodies[i].q);
  }
  ASSERT_EQ(a.walls.size(), b.walls.size());
  for (std::size_t i = 0; i < a.walls.size(); ++i) {
    expect_same(a.walls[i].x, b.walls[i].x);
    expect_same(a.walls[i].q, b.walls[i].q);
    expect_same(a.walls[i].v, b.walls[i].v);
    expect_same(a.walls[i].force, b.walls[i].force);
  }
  ASSERT_EQ(a.pairs.size(), b.pairs.size());
  for (std::size_t i = 0; i < a.pairs.size(); ++i) expect_same(a.pairs[i], b.pairs[i]);
  ASSERT_EQ(a.wall_pairs.size(), b.wall_pairs.size());
  for (std::size_t i = 0; i < a.wall_pairs.size(); ++i) expect_same(a.wall_pairs[i], b.wall_pairs[i]);
  ASSERT_EQ(a.contacts.size(), b.contacts.size());
  for (std::size_t i = 0; i < a.contacts.size(); ++i) expect_same(a.contacts[i], b.contacts[i]);
  ASSERT_EQ(a.wall_contacts.size(), b.wall_contacts.size());
  for (std::size_t i = 0; i < a.wall_contacts.size(); ++i) expect_same(a.wall_contacts[i], b.wall_contacts[i]);
  ASSERT_EQ(a.x_at_rebuild.size(), b.x_at_rebuild.size());
  for (std::size_t i = 0; i < a.x_at_rebuild.size(); ++i) expect_same(a.x_at_rebuild[i], b.x_at_rebuild[i]);
  ASSERT_EQ(a.piece_caches.size(), b.piece_caches.size());
  for (std::size_t i = 0; i < a.piece_caches.size(); ++i) expect_same(a.piece_caches[i], b.piece_caches[i]);
  ASSERT_EQ(a.wall_piece_caches.size(), b.wall_piece_caches.size());
  for (std::size_t i = 0; i < a.wall_piece_caches.size(); ++i)
    expect_same(a.wall_piece_caches[i], b.wall_piece_caches[i]);
  ASSERT_EQ(a.wall_x_at_rebuild.size(), b.wall_x_at_rebuild.size());
  ASSERT_EQ(a.wall_q_at_rebuild.size(), b.wall_q_at_rebuild.size());
  for (std::size_t i = 0; i < a.wall_x_at_rebuild.size(); ++i) {
    expect_same(a.wall_x_at_rebuild[i], b.wall_x_at_rebuild[i]);
    expect_same(a.wall_q_at_rebuild[i], b.wall_q_at_rebuild[i]);
  }
}

TEST(Checkpoint, RandomStateRoundTripsBitForBit) {
  test::IoTempDir dir;
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    RandomFill fill(seed);
    const State s = fill.state();
    std::vector<std::uint8_t> protocol(fill.n(100));
    for (auto& b : protocol) b = static_cast<std::uint8_t>(fill.i());
    const std::uint64_t hash = 0x0123456789abcdefull * seed;
    save_checkpoint(dir.path / "checkpoint.bin", s, protocol, hash);
    const Checkpoint c = load_checkpoint(dir.path / "checkpoint.bin");
    expect_same(c.state, s);
    EXPECT_EQ(c.protocol, protocol);
    EXPECT_EQ(c.config_hash, hash);
  }
}

TEST(Checkpoint, EmptyStateRoundTrips) {
  const State s;
  const Checkpoint c = decode_checkpoint(encode_checkpoint(s, {}, 0), "empty");
  expect_same(c.state, s);
  EXPECT_TRUE(c.protocol.empty());
}

std::string refusal(const std::vector<std::uint8_t>& bytes) {
  return test::error_of<InputError>([&] { decode_checkpoint(bytes, "ck.bin"); });
}

TEST(Checkpoint, TruncatedFileIsRefused) {
  RandomFill fill(11);
  const std::vector<std::uint8_t> good = encode_checkpoint(fill.state(), std::vector<std::uint8_t>{1, 2, 3}, 9);
  for (const std::size_t keep : {std::size_t{0}, std::size_t{5}, std::size_t{20}, good.size() / 2, good.size() - 1}) {
    const std::string msg = refusal({good.begin(), good.begin() + static_cast<std::ptrdiff_t>(keep)});
    EXPECT_NE(msg.find("ck.bin"), std::string::npos) << msg;
  }
  EXPECT_NE(refusal({good.begin(), good.end() - 1}).find("truncated"), std::string::npos);
}

TEST(Checkpoint, AnyFlippedByteIsRefused) {
  RandomFill fill(12);
  const std::vector<std::uint8_t> good = encode_checkpoint(fill.state(), std::vector<std::uint8_t>{4, 5}, 77);
  std::mt19937 rng(3);
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<std::uint8_t> bad = good;
    const std::size_t at = trial < 32 ? static_cast<std::size_t>(trial) : rng() % bad.size();
    if (at >= 12 && at < 16) continue;  // the grains' fingerprint: checked against the grains (same_grains)
    bad[at] ^= static_cast<std::uint8_t>(1u << (rng() % 8));
    EXPECT_THROW(decode_checkpoint(bad, "ck.bin"), InputError) << "byte " << at;
  }
  std::vector<std::uint8_t> flipped = good;
  flipped[100] ^= 0x10;
  EXPECT_NE(refusal(flipped).find("checksum"), std::string::npos);
}

TEST(Checkpoint, WrongVersionAndWrongFileAreRefused) {
  std::vector<std::uint8_t> bytes = encode_checkpoint(State{}, {}, 0);
  bytes[8] = 99;  // version, little-endian
  EXPECT_NE(refusal(bytes).find("version 99"), std::string::npos) << refusal(bytes);
  const std::string text = "seed = 1\n";
  const std::string msg = refusal({text.begin(), text.end()});
  EXPECT_NE(msg.find("not a grainlab checkpoint"), std::string::npos) << msg;
  const std::string missing = test::error_of<InputError>([] { load_checkpoint("/no/such/checkpoint.bin"); });
  EXPECT_NE(missing.find("/no/such/checkpoint.bin"), std::string::npos) << missing;
}

// The same checkpoint in format version 6 (before the wall poses): the
// trailing wall-pose count and poses cut off. `s` has no wall poses.
std::vector<std::uint8_t> as_version6(const std::vector<std::uint8_t>& v7) {
  constexpr std::size_t header = 32;
  const std::vector<std::uint8_t> out(v7.begin() + header, v7.end() - 8);
  ByteWriter file;
  file.bytes.assign(v7.begin(), v7.begin() + 8);
  file.u32(6), file.u32(0), file.u64(out.size()), file.u64(fnv1a64(out));
  file.bytes.insert(file.bytes.end(), out.begin(), out.end());
  return file.bytes;
}

// The same checkpoint in format version 5 (before the piece-pair caches):
// no piece-cache counts, no pieces field per pair, no caches. `s` has none.
std::vector<std::uint8_t> as_version5(const State& s, const std::vector<std::uint8_t>& v7) {
  constexpr std::size_t header = 32, pair_bytes = 73, count_at = 8 + 8 + 8 + 1;
  const std::vector<std::uint8_t> v6 = as_version6(v7);
  const std::vector<std::uint8_t> payload(v6.begin() + header, v6.end());
  std::vector<std::uint8_t> out(payload.begin(), payload.begin() + count_at + 8 * 8);  // the first 8 counts
  std::size_t at = count_at + 10 * 8;
  const std::size_t before_pairs = (s.bodies.size() + s.walls.size()) * 13 * 8;
  out.insert(out.end(), payload.begin() + at, payload.begin() + at + before_pairs);
  at += before_pairs;
  for (std::size_t k = 0; k < s.pairs.size() + s.wall_pairs.size(); ++k, at += pair_bytes)
    out.insert(out.end(), payload.begin() + at, payload.begin() + at + pair_bytes - 4);
  out.insert(out.end(), payload.begin() + at, payload.end());
  ByteWriter file;
  file.bytes.assign(v6.begin(), v6.begin() + 8);
  file.u32(5), file.u32(0), file.u64(out.size()), file.u64(fnv1a64(out));
  file.bytes.insert(file.bytes.end(), out.begin(), out.end());
  return file.bytes;
}

TEST(Checkpoint, AVersion5FileIsReadWithColdPieces) {
  RandomFill fill(21);
  State s = fill.state();
  s.piece_caches.clear(), s.wall_piece_caches.clear();
  for (CandidatePair& p : s.pairs) p.pieces = -1;
  for (CandidatePair& p : s.wall_pairs) p.pieces = -1;
  const std::vector<std::uint8_t> protocol{7, 8, 9};
  s.wall_x_at_rebuild.clear(), s.wall_q_at_rebuild.clear();
  const std::vector<std::uint8_t> v7 = encode_checkpoint(s, protocol, 42);
  const std::vector<std::uint8_t> v5 = as_version5(s, v7);
  ASSERT_EQ(v5.size(), v7.size() - 8 - 16 - 4 * (s.pairs.size() + s.wall_pairs.size()));
  const Checkpoint c = decode_checkpoint(v5, "v5.bin");
  expect_same(c.state, s);
  EXPECT_EQ(c.protocol, protocol);
  EXPECT_EQ(c.config_hash, 42u);
}

TEST(Checkpoint, AVersion6FileIsReadWithoutWallPoses) {
  // Its world of spheres finds its wall candidates anew (empty poses).
  RandomFill fill(23);
  State s = fill.state();
  s.wall_x_at_rebuild.clear(), s.wall_q_at_rebuild.clear();
  const std::vector<std::uint8_t> protocol{1, 2};
  const std::vector<std::uint8_t> v6 = as_version6(encode_checkpoint(s, protocol, 43));
  const Checkpoint c = decode_checkpoint(v6, "v6.bin");
  expect_same(c.state, s);
  EXPECT_EQ(c.protocol, protocol);
}

TEST(Checkpoint, APairsPieceCachesOutsideTheirListAreRefused) {
  RandomFill fill(22);
  State s = fill.state();
  s.piece_caches.resize(3);
  s.pairs[0].pieces = 3;
  EXPECT_NE(refusal(encode_checkpoint(s, {}, 0)).find("piece caches"), std::string::npos);
}

TEST(Checkpoint, TheGrainsFingerprintTravelsWithTheFileAndTellsOtherGrains) {
  Model m;
  const Index cube = m.add_mesh_shape(box_mesh(1e-3, 1e-3, 1e-3), "cube");
  const Index ball = m.add_sphere_shape(5e-4);
  m.add_material(Material{});
  const auto body = [&](Index shape, double scale) {
    BodyModel b;
    b.shape = shape, b.scale = scale;
    m.bodies.push_back(b);
  };
  body(cube, 1.0), body(ball, 1.0);
  const std::uint32_t f = grains_fingerprint(m);
  EXPECT_NE(f, 0u);
  const Checkpoint c = decode_checkpoint(encode_checkpoint(State{}, {}, 3, f), "ck.bin");
  EXPECT_EQ(c.grains, f);
  EXPECT_TRUE(same_grains(c, m));
  Model scaled = m;
  scaled.bodies[1].scale = 1.01;
  EXPECT_FALSE(same_grains(c, scaled));
  Model moved = m;
  moved.shapes[cube].mesh.vertices[0].x() += 1e-9;  // a generator that moved one vertex by a nanometre
  EXPECT_FALSE(same_grains(c, moved));
  Model other_material = m;
  other_material.materials[0].friction = 0.5;  // a specimen may be sheared with another material
  EXPECT_TRUE(same_grains(c, other_material));
  EXPECT_TRUE(same_grains(decode_checkpoint(encode_checkpoint(State{}, {}, 3), "old.bin"), moved));  // not recorded
}

TEST(Checkpoint, ConfigHashFollowsTheConfig) {
  LabSpec a, b;
  EXPECT_EQ(config_hash(a), config_hash(b));
  b.consolidation.normal_stress = 100e3 + 1e-9;
  EXPECT_NE(config_hash(a), config_hash(b));
  EXPECT_EQ(fnv1a64({}), 0xcbf29ce484222325ull);
  const std::uint8_t a_byte[] = {'a'};
  EXPECT_EQ(fnv1a64(a_byte), 0xaf63dc4c8601ec8cull);  // published FNV-1a 64 test vector for "a"
}

}  // namespace
}  // namespace grainlab
