// Checkpoint encoding. Every number is written little-endian byte by byte
// (doubles as their IEEE-754 bits), so files are exact and portable, and
// struct padding never reaches the file. Payload order:
//   config_hash u64, time f64, step i64, rebuild_pairs u8,
//   counts u64: bodies, walls, pairs, wall_pairs, contacts, wall_contacts,
//            x_at_rebuild, protocol, piece_caches, wall_piece_caches,
//   bodies   (x, v, w: 3 f64 each; q: x, y, z, w),
//   walls    (x, q, v, force),
//   pairs, wall_pairs (a, b i32; cache; pieces i32), where a cache is
//            dir; hint_a, hint_b i32; warm u8; simplex: n i32, a[3], b[3] i32,
//   contacts, wall_contacts (a, b, sub i32; xi; geo: touching u8, depth,
//            normal, point, spread, gain, twist; force, torque, normal_force),
//   x_at_rebuild (3 f64 each), protocol bytes, piece_caches and
//   wall_piece_caches (a cache each),
//   wall_rebuild count u64, then per wall its pose at the wall candidates'
//   last finding (x, q; a world of spheres keeps them, World::broadphase).
// Version 5 (before the piece-pair caches) is read too: no piece-cache
// counts, no pieces field, no caches; its pairs of concave grains then
// start their pieces cold, as a new pair does (a run resumed from it is
// deterministic, not the bits of the run that wrote it). So is version 6
// (before the wall poses): a world of spheres resumed from it finds its wall
// candidates anew, the same contacts from a list that may differ.
#include "io/checkpoint.h"

#include "core/bounded_read.h"
#include "core/bytes.h"
#include "core/error.h"
#include "core/atomic_file.h"
#include "io/config.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>

#include <unistd.h>

namespace grainlab {

// A new field in these structs must be written below (and the version bumped).
// ContactResult::share is not written: the narrowphase sets it again before
// the next forces (as it does every geometric field of a contact), and a
// contact read back carries share 1, as it carries what it did not store.
static_assert(sizeof(ContactResult) == 112, "ContactResult changed: update io/checkpoint.cpp and kCheckpointVersion");
static_assert(sizeof(PairCache) == 64, "PairCache changed: update io/checkpoint.cpp and kCheckpointVersion");
// CandidatePair::first_contact and pieces_cold are hints, not state: they are
// not written and read back as kUnknownContacts and false.
static_assert(sizeof(CandidatePair) == 88, "CandidatePair changed: update io/checkpoint.cpp and kCheckpointVersion");
static_assert(sizeof(Contact) == 208, "Contact changed: update io/checkpoint.cpp and kCheckpointVersion");

namespace {

constexpr char kMagic[8] = {'G', 'L', 'C', 'K', 'P', 'T', '\r', '\n'};
constexpr std::size_t kHeaderSize = 8 + 4 + 4 + 8 + 8;

// The portable byte writer/reader of core/bytes.h, with the checkpoint's messages.
using Writer = ByteWriter;
using Reader = ByteReader;

Reader checkpoint_reader(std::span<const std::uint8_t> bytes, const std::string& source) {
  return Reader(bytes, fmt::format("checkpoint '{}'", source),
                " Delete it and start the run again without --resume.");
}

// The first version without the piece-pair caches, and the last without the
// wall poses, still read.
constexpr std::uint32_t kVersionWithoutPieces = 5;
constexpr std::uint32_t kVersionWithoutWallPoses = 6;

void write_cache(Writer& w, const PairCache& c) {
  w.vec(c.dir);
  w.i32(c.hint_a), w.i32(c.hint_b);
  w.u8(c.warm ? 1 : 0);
  w.i32(c.simplex.n);
  for (int i = 0; i < 3; ++i) w.i32(c.simplex.a[i]), w.i32(c.simplex.b[i]);
}

PairCache read_cache(Reader& r) {
  PairCache c;
  c.dir = r.vec();
  c.hint_a = r.i32(), c.hint_b = r.i32();
  c.warm = r.flag();
  c.simplex.n = r.i32();
  for (int i = 0; i < 3; ++i) c.simplex.a[i] = r.i32(), c.simplex.b[i] = r.i32();
  return c;
}

void write_pair(Writer& w, const CandidatePair& p) {
  w.i32(p.a), w.i32(p.b);
  write_cache(w, p.cache);
  w.i32(p.pieces);
}

CandidatePair read_pair(Reader& r, bool with_pieces) {
  CandidatePair p;
  p.a = r.i32(), p.b = r.i32();
  p.cache = read_cache(r);
  if (with_pieces) p.pieces = r.i32();
  return p;
}

void write_contact(Writer& w, const Contact& p) {
  w.i32(p.a), w.i32(p.b), w.i32(p.sub);
  w.vec(p.xi);
  w.u8(p.geo.touching ? 1 : 0);
  w.f64(p.geo.depth);
  w.vec(p.geo.normal), w.vec(p.geo.point);
  w.f64(p.geo.spread);
  w.f64(p.geo.gain), w.vec(p.geo.twist);
  w.vec(p.force), w.vec(p.torque);
  w.f64(p.normal_force);
}

Contact read_contact(Reader& r) {
  Contact p;
  p.a = r.i32(), p.b = r.i32(), p.sub = r.i32();
  p.xi = r.vec();
  p.geo.touching = r.flag();
  p.geo.depth = r.f64();
  p.geo.normal = r.vec(), p.geo.point = r.vec();
  p.geo.spread = r.f64();
  p.geo.gain = r.f64(), p.geo.twist = r.vec();
  p.force = r.vec(), p.torque = r.vec();
  p.normal_force = r.f64();
  return p;
}

constexpr std::size_t kBodyBytes = 13 * 8;
constexpr std::size_t kWallBytes = 13 * 8;
constexpr std::size_t kWallPoseBytes = 7 * 8;  // x, q
constexpr std::size_t kCacheBytes = 2 * 4 + 1 + 3 * 8 + 7 * 4;
constexpr std::size_t kPairBytes = 2 * 4 + kCacheBytes + 4;
constexpr std::size_t kContactBytes = 3 * 4 + 1 + 22 * 8;

}  // namespace

std::uint64_t fnv1a64(std::span<const std::uint8_t> bytes) {
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (const std::uint8_t b : bytes) {
    h ^= b;
    h *= 0x100000001b3ull;
  }
  return h;
}

std::uint64_t specimen_hash(const LabSpec& spec) {
  LabSpec key;  // every other field at its default
  key.test = spec.test;
  key.seed = spec.seed;
  key.grains = spec.grains;
  key.box = spec.box;
  key.consolidation.normal_stress = spec.consolidation.normal_stress;
  key.numerics.density_scaling = spec.numerics.density_scaling;
  return config_hash(key);
}

std::uint64_t config_hash(const LabSpec& spec) {
  const std::string text = to_toml(spec);
  return fnv1a64({reinterpret_cast<const std::uint8_t*>(text.data()), text.size()});
}

std::uint32_t grains_fingerprint(const Model& model) {
  Writer w;
  for (const Shape& s : model.shapes) {
    w.u8(static_cast<std::uint8_t>(s.kind));
    w.f64(s.volume), w.vec(s.unit_moments), w.f64(s.equivalent_radius), w.f64(s.bounding_radius);
    w.u64(s.mesh.vertices.size());
    for (const Vec3& v : s.mesh.vertices) w.vec(v);
  }
  for (const BodyModel& b : model.bodies) w.i32(b.shape), w.f64(b.scale);
  const std::uint64_t h = fnv1a64(w.bytes);
  const auto folded = static_cast<std::uint32_t>(h ^ (h >> 32));
  return folded == 0 ? 1 : folded;
}

bool same_grains(const Checkpoint& c, const Model& model) {
  return c.grains == 0 || c.grains == grains_fingerprint(model);
}

std::vector<std::uint8_t> encode_checkpoint(const State& state, std::span<const std::uint8_t> protocol,
                                            std::uint64_t config_hash, std::uint32_t grains) {
  Writer p;
  p.u64(config_hash);
  p.f64(state.time);
  p.i64(state.step);
  p.u8(state.rebuild_pairs ? 1 : 0);
  p.u64(state.bodies.size()), p.u64(state.walls.size()), p.u64(state.pairs.size());
  p.u64(state.wall_pairs.size()), p.u64(state.contacts.size()), p.u64(state.wall_contacts.size());
  p.u64(state.x_at_rebuild.size()), p.u64(protocol.size());
  p.u64(state.piece_caches.size()), p.u64(state.wall_piece_caches.size());
  for (const BodyState& b : state.bodies) p.vec(b.x), p.vec(b.v), p.vec(b.w), p.quat(b.q);
  for (const WallState& w : state.walls) p.vec(w.x), p.quat(w.q), p.vec(w.v), p.vec(w.force);
  for (const CandidatePair& c : state.pairs) write_pair(p, c);
  for (const CandidatePair& c : state.wall_pairs) write_pair(p, c);
  for (const Contact& c : state.contacts) write_contact(p, c);
  for (const Contact& c : state.wall_contacts) write_contact(p, c);
  for (const Vec3& x : state.x_at_rebuild) p.vec(x);
  p.bytes.insert(p.bytes.end(), protocol.begin(), protocol.end());
  for (const PairCache& c : state.piece_caches) write_cache(p, c);
  for (const PairCache& c : state.wall_piece_caches) write_cache(p, c);
  const std::size_t wall_poses = std::min(state.wall_x_at_rebuild.size(), state.wall_q_at_rebuild.size());
  p.u64(wall_poses);
  for (std::size_t w = 0; w < wall_poses; ++w) p.vec(state.wall_x_at_rebuild[w]), p.quat(state.wall_q_at_rebuild[w]);

  Writer file;
  file.bytes.assign(std::begin(kMagic), std::end(kMagic));
  file.u32(kCheckpointVersion);
  file.u32(grains);
  file.u64(p.bytes.size());
  file.u64(fnv1a64(p.bytes));
  file.bytes.insert(file.bytes.end(), p.bytes.begin(), p.bytes.end());
  return std::move(file.bytes);
}

Checkpoint decode_checkpoint(std::span<const std::uint8_t> bytes, const std::string& source_name) {
  if (bytes.size() < 8 || std::memcmp(bytes.data(), kMagic, 8) != 0)
    input_error("'{}' is not a grainlab checkpoint (its first bytes are not the checkpoint signature). "
                "Give the checkpoint.bin of a run folder.",
                source_name);
  Reader header = checkpoint_reader(bytes.subspan(8), source_name);
  const std::uint32_t version = header.u32();
  if (version < kVersionWithoutPieces || version > kCheckpointVersion)
    input_error("checkpoint '{}' has format version {}, this grainlab reads versions {} to {}. Resume it with the "
                "grainlab that wrote it, or start the run again without --resume.",
                source_name, version, kVersionWithoutPieces, kCheckpointVersion);
  const bool with_pieces = version > kVersionWithoutPieces;
  const std::uint32_t grains = header.u32();
  const std::uint64_t size = header.u64();
  const std::uint64_t checksum = header.u64();
  if (bytes.size() - kHeaderSize != size)
    input_error("checkpoint '{}' is truncated or damaged: its header announces {} bytes of data, the file holds "
                "{}. Delete it and start the run again without --resume.",
                source_name, size, bytes.size() - kHeaderSize);
  const std::span<const std::uint8_t> payload = bytes.subspan(kHeaderSize);
  if (fnv1a64(payload) != checksum)
    input_error("checkpoint '{}' is corrupted (checksum mismatch). Delete it and start the run again without "
                "--resume.",
                source_name);

  Reader r = checkpoint_reader(payload, source_name);
  Checkpoint c;
  c.grains = grains;
  c.config_hash = r.u64();
  State& s = c.state;
  s.time = r.f64();
  s.step = r.i64();
  s.rebuild_pairs = r.flag();
  const std::size_t n_bodies = r.count(kBodyBytes), n_walls = r.count(kWallBytes);
  const std::size_t pair_bytes = with_pieces ? kPairBytes : kPairBytes - 4;
  const std::size_t n_pairs = r.count(pair_bytes), n_wall_pairs = r.count(pair_bytes);
  const std::size_t n_contacts = r.count(kContactBytes), n_wall_contacts = r.count(kContactBytes);
  const std::size_t n_rebuild = r.count(24), n_protocol = r.count(1);
  const std::size_t n_pieces = with_pieces ? r.count(kCacheBytes) : 0;
  const std::size_t n_wall_pieces = with_pieces ? r.count(kCacheBytes) : 0;
  s.bodies.resize(n_bodies);
  for (BodyState& b : s.bodies) b.x = r.vec(), b.v = r.vec(), b.w = r.vec(), b.q = r.quat();
  s.walls.resize(n_walls);
  for (WallState& w : s.walls) w.x = r.vec(), w.q = r.quat(), w.v = r.vec(), w.force = r.vec();
  s.pairs.reserve(n_pairs);
  for (std::size_t i = 0; i < n_pairs; ++i) s.pairs.push_back(read_pair(r, with_pieces));
  s.wall_pairs.reserve(n_wall_pairs);
  for (std::size_t i = 0; i < n_wall_pairs; ++i) s.wall_pairs.push_back(read_pair(r, with_pieces));
  s.contacts.reserve(n_contacts);
  for (std::size_t i = 0; i < n_contacts; ++i) s.contacts.push_back(read_contact(r));
  s.wall_contacts.reserve(n_wall_contacts);
  for (std::size_t i = 0; i < n_wall_contacts; ++i) s.wall_contacts.push_back(read_contact(r));
  s.x_at_rebuild.resize(n_rebuild);
  for (Vec3& x : s.x_at_rebuild) x = r.vec();
  c.protocol.resize(n_protocol);
  for (std::uint8_t& b : c.protocol) b = r.u8();
  s.piece_caches.resize(n_pieces);
  for (PairCache& pc : s.piece_caches) pc = read_cache(r);
  s.wall_piece_caches.resize(n_wall_pieces);
  for (PairCache& pc : s.wall_piece_caches) pc = read_cache(r);
  if (version > kVersionWithoutWallPoses) {
    s.wall_x_at_rebuild.resize(r.count(kWallPoseBytes));
    s.wall_q_at_rebuild.resize(s.wall_x_at_rebuild.size());
    for (std::size_t w = 0; w < s.wall_x_at_rebuild.size(); ++w)
      s.wall_x_at_rebuild[w] = r.vec(), s.wall_q_at_rebuild[w] = r.quat();
  }
  for (const auto& [pairs, pool] : {std::pair{&s.pairs, &s.piece_caches}, std::pair{&s.wall_pairs, &s.wall_piece_caches}})
    for (const CandidatePair& p : *pairs)
      if (p.pieces < -1 || (p.pieces >= 0 && static_cast<std::size_t>(p.pieces) >= pool->size()))
        r.corrupted("a pair's piece caches lie outside their list");
  if (r.left() != 0) r.corrupted("bytes left over after the last field");
  return c;
}

void save_checkpoint(const std::filesystem::path& path, const State& state, std::span<const std::uint8_t> protocol,
                     std::uint64_t config_hash, std::uint32_t grains) {
  const std::vector<std::uint8_t> bytes = encode_checkpoint(state, protocol, config_hash, grains);
  write_file_atomically(path, {reinterpret_cast<const char*>(bytes.data()), bytes.size()});
}

Checkpoint load_checkpoint(const std::filesystem::path& path) {
  if (::access(path.c_str(), R_OK) != 0)
    input_error("cannot open checkpoint '{}': it does not exist or is not readable. A run writes checkpoint.bin "
                "into its output folder; run without --resume to start afresh.",
                path.string());
  // Every count inside is checked against the bytes that follow it (core/bytes.h).
  const std::string bytes = read_bounded_file(path, kMaxCheckpointBytes, "checkpoint");
  return decode_checkpoint({reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()}, path.string());
}

}  // namespace grainlab
