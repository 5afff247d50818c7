// The own index void ratios of the embedded default's grains, measured once
// and shipped in the binary, so that the demo (`grainlab run --default`)
// targets a Dr on its grains' own indices without the ten-minute index
// measurement a run makes for grains it does not know. A second record holds
// those of the 2000-bead direct shear that grainlab is compared with other
// sphere codes on (bench/liggghts/beads_direct_shear.toml: glass beads, its
// material and time step), whose measurement (about 65,000 steps, a fifth of
// that test's wall time) the other codes do not make. Two more hold those of
// the sh-ottawa and sh-river presets with every other key at their defaults
// (an hour of one core each to measure).
//
// They are what `grainlab run` itself would measure (lab/index_densities.h,
// one seed at the run's seed), for exactly the default inputs that the
// measurement depends on: the record holds the hash of their
// index_cache_key (seed, grains, material, consolidation stress, numerics
// but the thread count and the loading speed)
// and is taken only by a spec with the same key. A run of other grains, or
// of the default grains under another seed, material or numerics, measures
// its own (or reads its index_densities.json). The record also holds the
// grains_fingerprint of the default specimen's Model; a test
// (tests/io/embedded_indices_test.cpp) fails when the key or the grains the
// generator makes have changed, with the command that measures them again.
// Each record is taken only for its own inputs: beads of another size range,
// material, time step or seed measure their own.
#pragma once

#include "lab/lab_spec.h"

#include <cstdint>
#include <optional>

namespace grainlab {

struct EmbeddedIndices {
  std::uint64_t key_hash;        // fnv1a64 of index_cache_key() of the inputs measured
  std::uint32_t grains;          // grains_fingerprint() of the default direct shear specimen's Model
  double e_min, e_max;           // bulk void ratios (lab/packing_density.h)
  double e_min_whole, e_max_whole;  // whole index box, for the record
  const char* how;               // when and with what command they were measured
};

// The record for the embedded default's grains.
const EmbeddedIndices& default_grain_indices();

// The record for the beads of bench/liggghts/beads_direct_shear.toml.
const EmbeddedIndices& bench_bead_indices();

// The records for the default config with [grains] preset = "sh-ottawa",
// and with preset = "sh-river".
const EmbeddedIndices& sh_ottawa_indices();
const EmbeddedIndices& sh_river_indices();

// fnv1a64 of index_cache_key(spec).
std::uint64_t index_key_hash(const LabSpec& spec);

// The embedded record whose index inputs are spec's; nullopt if none.
std::optional<EmbeddedIndices> embedded_index_densities(const LabSpec& spec);

}  // namespace grainlab
