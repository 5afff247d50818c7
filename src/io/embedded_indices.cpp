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

const EmbeddedIndices& bench_bead_indices() {
  // Measured 2026-12-06 by `grainlab run bench/liggghts/beads_direct_shear.toml`
  // (glass beads 0.707-0.841 mm, E 4 GPa, nu 0.25, restitution 0.5, friction
  // 0.12, frictionless walls, dt 4.674e-7 s, density scaling 1, 100 kPa, seed 1;
  // one thread, the machine shared; index box 10 x 8 d_max, 1,146 beads).
  // e_min: frictionless deposition and compaction, 43,600 steps, 28 s; e_max:
  // deposition at friction 1.0, 22,100 steps, 13 s.
  static const EmbeddedIndices record{
      0x12b44526d626e143ull, 0x1a91e7d3u, 0.5803851395791362, 0.7436361557686755, 0.6862646507990815, 1.0636276395489754,
      "measured 2026-12-06 with `grainlab run bench/liggghts/beads_direct_shear.toml` (seed 1)"};
  return record;
}

const EmbeddedIndices& sh_ottawa_indices() {
  // Measured 2026-12-07 on the project's 2-core machine by `grainlab grains
  // index --preset sh-ottawa --seeds 1 --threads 1` (the default config with
  // [grains] preset = "sh-ottawa": 24 shapes of 200 faces, 0.707-0.841 mm,
  // seed 1; index box 10 x 8 d_max, 1,540 grains), the machine shared.
  // e_min: frictionless deposition and compaction at 100 kPa, 35,500 steps,
  // 3,567 s; e_max: deposition at friction 1.0, 10,050 steps, 289 s.
  static const EmbeddedIndices record{
      0xe207c6431ecfb4a7ull, 0x887d2105u, 0.49625250263200993, 0.8070688195049864, 0.5804473856225718, 1.0634213363787612,
      "measured 2026-12-07 with `grainlab grains index --preset sh-ottawa --seeds 1` (seed 1)"};
  return record;
}

const EmbeddedIndices& sh_river_indices() {
  // Measured 2026-12-07 on the project's 2-core machine by `grainlab grains
  // index --preset sh-river --seeds 1 --threads 1` (the default config with
  // [grains] preset = "sh-river": 24 shapes of 200 faces, 0.707-0.841 mm,
  // seed 1; index box 10 x 8 d_max, 1,838 grains), the machine shared.
  // e_min: frictionless deposition and compaction at 100 kPa, 40,900 steps,
  // 3,753 s; e_max: deposition at friction 1.0, 12,200 steps, 394 s.
  static const EmbeddedIndices record{
      0xd8b51b1fac884d6bull, 0xaf1b3056u, 0.5044328445776496, 0.771152771725204, 0.5750369089987621, 1.0527799341463053,
      "measured 2026-12-07 with `grainlab grains index --preset sh-river --seeds 1` (seed 1)"};
  return record;
}

std::uint64_t index_key_hash(const LabSpec& spec) {
  const std::string key = index_cache_key(spec);
  return fnv1a64(std::span(reinterpret_cast<const std::uint8_t*>(key.data()), key.size()));
}

std::optional<EmbeddedIndices> embedded_index_densities(const LabSpec& spec) {
  const std::uint64_t key = index_key_hash(spec);
  for (const EmbeddedIndices* r :
       {&default_grain_indices(), &bench_bead_indices(), &sh_ottawa_indices(), &sh_river_indices()})
    if (key == r->key_hash) return *r;
  return std::nullopt;
}

}  // namespace grainlab
