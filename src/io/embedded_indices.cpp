// The embedded default's own index void ratios (see embedded_indices.h).
#include "io/embedded_indices.h"

#include "io/checkpoint.h"
#include "io/preparation_files.h"

#include <span>
#include <string>

namespace grainlab {

const EmbeddedIndices& default_grain_indices() {
  // Measured 2026-12-04 on the project's 2-core machine by `grainlab run`
  // of the default config (rounded, 24 shapes of 200 faces, 0.707-0.841 mm,
  // seed 1) with own_e_min = own_e_max = 0, one thread, the machine shared
  // (what `grainlab grains index --preset rounded --faces 200 --seeds 1`
  // measures; index box 10 x 8 d_max, 1,185 grains). e_min: frictionless
  // deposition and compaction at 100 kPa, 14,300 steps, 203 s; e_max:
  // deposition at friction 1.0, no compaction, 3,450 steps, 42 s.
  static const EmbeddedIndices record{
      0xb6ca65bfe49419c6ull, 0x9b40bf1eu, 0.4128053050489928, 0.6653608803125799, 0.4950382620566238, 0.9332264019271701,
      "measured 2026-12-04 with `grainlab run` of the default config (seed 1, the default grains)"};
  return record;
}

std::uint64_t index_key_hash(const LabSpec& spec) {
  const std::string key = index_cache_key(spec);
  return fnv1a64(std::span(reinterpret_cast<const std::uint8_t*>(key.data()), key.size()));
}

std::optional<EmbeddedIndices> embedded_index_densities(const LabSpec& spec) {
  const EmbeddedIndices& r = default_grain_indices();
  if (index_key_hash(spec) != r.key_hash) return std::nullopt;
  return r;
}

}  // namespace grainlab
