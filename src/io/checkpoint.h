// Checkpoints: the whole changing State of a run (poses, velocities, walls,
// every contact's history, the Verlet bookkeeping), the lab protocol's own
// bytes (its phase, controller state), and the hash of the config that made
// it. Binary, little-endian, exact (raw IEEE bits), written atomically.
//
// Layout: magic "GLCKPT\r\n" (8 bytes), format version (u32), the grains'
// fingerprint (u32; 0 in files written before session 17: unknown), payload
// size (u64), FNV-1a 64 checksum of the payload (u64), payload. The payload
// is the config hash, the State and the protocol bytes; see checkpoint.cpp
// for the field order.
//
// The config hash says which config made the run; the grains' fingerprint
// says which grains this grainlab made from it. The grains are made again
// from the config when a run resumes (generated, or imported and
// decomposed), so a grainlab whose generator changed would otherwise
// resume on other grains without a word.
#pragma once

#include "dynamics/model.h"
#include "dynamics/state.h"
#include "lab/lab_spec.h"

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace grainlab {

// What a checkpoint file holds.
struct Checkpoint {
  State state;
  std::vector<std::uint8_t> protocol;  // opaque bytes of the lab protocol
  std::uint64_t config_hash = 0;       // config_hash() of the run's spec
  std::uint32_t grains = 0;            // grains_fingerprint() of its Model; 0: not recorded
};

// A fingerprint of the grains of a Model: each shape's kind, volume,
// moments, radii and surface vertices (raw bits), each body's shape and
// scale; not the materials (a specimen may be sheared with another). Never 0.
std::uint32_t grains_fingerprint(const Model& model);

// Whether a checkpoint's grains are `model`'s: the same fingerprint, or one
// not recorded (an older file).
bool same_grains(const Checkpoint& c, const Model& model);

// Current checkpoint format version; files of another version are refused.
// 2: candidate pairs (warm-start caches) and contacts (a, b, sub-contact) stored apart;
//    protocol bytes through core/bytes.h, no Model fields.
inline constexpr std::uint32_t kCheckpointVersion = 7;  // 3: contacts carry gain and twist; 4: pairs carry their GJK simplex; 5: the oedometer keeps its last row's stress; 6: pairs of concave grains keep their piece pairs' caches; 7: the wall poses a world of spheres found its wall candidates at (5 and 6 are read too)

// What a prepared specimen depends on (grains, box, seed, test, consolidation
// stress, density scaling) as a hash: a specimen.bin (a checkpoint written as
// loading began, with this in place of config_hash) fits any spec with the
// same hash, whatever its material, damping or loading.
std::uint64_t specimen_hash(const LabSpec& spec);

// Writes a checkpoint atomically (RunError on failure).
void save_checkpoint(const std::filesystem::path& path, const State& state, std::span<const std::uint8_t> protocol,
                     std::uint64_t config_hash, std::uint32_t grains = 0);

// The largest checkpoint load_checkpoint reads (64 GiB: a paper-size run of
// 37,000 grains checkpoints in tens of megabytes); larger is no checkpoint.
inline constexpr std::uintmax_t kMaxCheckpointBytes = std::uintmax_t{64} << 30;

// Reads a checkpoint; throws InputError for a missing, truncated, corrupted,
// oversized, non-regular (a device) or wrong-version file.
Checkpoint load_checkpoint(const std::filesystem::path& path);

// The checkpoint file's bytes (save_checkpoint writes exactly these).
std::vector<std::uint8_t> encode_checkpoint(const State& state, std::span<const std::uint8_t> protocol,
                                            std::uint64_t config_hash, std::uint32_t grains = 0);
// Decodes checkpoint bytes; source_name is used in messages.
Checkpoint decode_checkpoint(std::span<const std::uint8_t> bytes, const std::string& source_name);

// FNV-1a 64-bit hash of bytes.
std::uint64_t fnv1a64(std::span<const std::uint8_t> bytes);
// Hash of to_toml(spec): a resumed run checks it against the checkpoint's.
std::uint64_t config_hash(const LabSpec& spec);

}  // namespace grainlab
