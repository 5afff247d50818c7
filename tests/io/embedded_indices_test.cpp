// The embedded default's own index void ratios (io/embedded_indices.h) are
// taken by the default spec and by nothing else, and still belong to the
// grains the generator makes for it: when the default's index inputs or its
// grains change, the first test fails and says how to measure them again.
#include "io/checkpoint.h"
#include "io/config.h"
#include "io/embedded_indices.h"
#include "lab/direct_shear.h"

#include <gtest/gtest.h>

using namespace grainlab;

namespace {

const char* kRemeasure =
    "the embedded default's own index void ratios were measured for other inputs or other grains. Measure "
    "them again with `build/grainlab grains index --seeds 1 --threads 1` (about 10 minutes) and put e_min, "
    "e_max, this key hash and this fingerprint in src/io/embedded_indices.cpp";

}  // namespace

TEST(EmbeddedIndices, BelongToTheDefaultInputsAndTheGrainsMadeForThem) {
  const LabSpec spec;
  const EmbeddedIndices& r = default_grain_indices();
  EXPECT_EQ(index_key_hash(spec), r.key_hash) << kRemeasure << " (key hash 0x" << std::hex << index_key_hash(spec)
                                              << ")";
  LabSpec known = spec;
  known.specimen.own_e_min = r.e_min;
  known.specimen.own_e_max = r.e_max;
  const DirectShearTest test(known);
  const std::uint32_t grains = grains_fingerprint(test.world().model);
  EXPECT_EQ(grains, r.grains) << kRemeasure << " (fingerprint 0x" << std::hex << grains << ")";
  // A packing's own indices: the loosest above the densest, both physical for faceted grains.
  EXPECT_GT(r.e_min, 0.3);
  EXPECT_GT(r.e_max, r.e_min + 0.1);
  EXPECT_LT(r.e_max, 1.0);
  EXPECT_GT(r.e_min_whole, r.e_min);  // the layer at the walls is looser than the bulk
  EXPECT_GT(r.e_max_whole, r.e_max);
}

TEST(EmbeddedIndices, AreTakenOnlyForTheDefaultsIndexInputs) {
  LabSpec spec;
  ASSERT_TRUE(embedded_index_densities(spec));
  // What the index measurement does not depend on leaves them.
  spec.numerics.threads = 1;
  spec.output.folder = "elsewhere";
  spec.specimen.relative_density = 0.3;
  spec.box.length *= 2;  // the index box is 10 d_max across whatever the test's box
  spec.settings<ShearSpec>().final_strain = 0.2;
  spec.numerics.inertial_number *= 5;  // the loading speed, after the preparation (preset_runs_test.cpp)
  EXPECT_TRUE(embedded_index_densities(spec));
  // What it depends on does not.
  const auto other = [](auto change) {
    LabSpec s;
    change(s);
    return embedded_index_densities(s).has_value();
  };
  EXPECT_FALSE(other([](LabSpec& s) { s.seed = 2; }));
  EXPECT_FALSE(other([](LabSpec& s) { s.grains.preset = "sub-angular"; }));
  EXPECT_FALSE(other([](LabSpec& s) { s.grains.faces = 1000; }));
  EXPECT_FALSE(other([](LabSpec& s) { s.grains.d_max = 1e-3; }));
  EXPECT_FALSE(other([](LabSpec& s) { s.grains.folder = "my_grains"; }));
  EXPECT_FALSE(other([](LabSpec& s) { s.material.grain.friction = 0.3; }));
  EXPECT_FALSE(other([](LabSpec& s) { s.consolidation.normal_stress = 200e3; }));
  EXPECT_FALSE(other([](LabSpec& s) { s.numerics.time_step_fraction = 0.2; }));
}

// The beads of the comparison with other sphere codes: the record belongs to
// the bench's config (bench/liggghts/beads_direct_shear.toml, read here) and
// to the beads grainlab places for it, and to nothing else.
TEST(EmbeddedIndices, BelongToTheBenchBeadsAndNothingElse) {
  const LabSpec spec = load_config(std::filesystem::path(GRAINLAB_TEST_DATA) / ".." / ".." / "bench" / "liggghts" /
                                   "beads_direct_shear.toml");
  const EmbeddedIndices& r = bench_bead_indices();
  EXPECT_EQ(index_key_hash(spec), r.key_hash)
      << "the beads' embedded indices were measured for other inputs: run `build/grainlab run "
         "bench/liggghts/beads_direct_shear.toml --threads 1` with the record's key hash set to 0, and put the "
         "e_min, e_max of its index_densities.json, this key hash and this fingerprint in "
         "src/io/embedded_indices.cpp (key hash 0x"
      << std::hex << index_key_hash(spec) << ")";
  LabSpec known = spec;
  known.specimen.own_e_min = r.e_min;
  known.specimen.own_e_max = r.e_max;
  const DirectShearTest test(known);
  const std::uint32_t grains = grains_fingerprint(test.world().model);
  EXPECT_EQ(grains, r.grains) << "the beads placed for the bench's config changed (fingerprint 0x" << std::hex
                              << grains << "): measure the record again as above";
  const auto taken = embedded_index_densities(spec);
  ASSERT_TRUE(taken);
  EXPECT_EQ(taken->e_min, r.e_min);
  // Near-monosized spheres: the bulk densest near random close packing (e about 0.56), the loosest looser.
  EXPECT_GT(r.e_min, 0.5);
  EXPECT_LT(r.e_min, 0.65);
  EXPECT_GT(r.e_max, r.e_min + 0.1);
  EXPECT_LT(r.e_max, 0.9);
  const auto other = [&](auto change) {
    LabSpec s = spec;
    change(s);
    return embedded_index_densities(s).has_value();
  };
  EXPECT_FALSE(other([](LabSpec& s) { s.grains.d_max = 1e-3; }));
  EXPECT_FALSE(other([](LabSpec& s) { s.material.grain.poisson_ratio = 0.3; }));
  EXPECT_FALSE(other([](LabSpec& s) { s.numerics.time_step = 4e-7; }));
  EXPECT_FALSE(other([](LabSpec& s) { s.seed = 2; }));
  EXPECT_TRUE(other([](LabSpec& s) { s.box.length = 0.02; }));  // the index box is 10 d_max whatever the test's box
}

// The sh-ottawa preset's record: the default config with that preset, and the
// spherical-harmonic grains the shape model draws for it; nothing else.
namespace {

// An SH preset's record belongs to the default config with that preset (its
// key and its grains), and to nothing else near it.
void expect_sh_preset_record(const std::string& preset, const EmbeddedIndices& r) {
  LabSpec spec;
  spec.grains.preset = preset;
  EXPECT_EQ(index_key_hash(spec), r.key_hash)
      << "the " << preset << " preset's embedded indices were measured for other inputs: measure them again with "
      << "`build/grainlab grains index --preset " << preset << " --seeds 1 --threads 1` (about an hour) and put "
      << "e_min, e_max, this key hash and this fingerprint in src/io/embedded_indices.cpp (key hash 0x" << std::hex
      << index_key_hash(spec) << ")";
  LabSpec known = spec;
  known.specimen.own_e_min = r.e_min;
  known.specimen.own_e_max = r.e_max;
  const DirectShearTest test(known);
  const std::uint32_t grains = grains_fingerprint(test.world().model);
  EXPECT_EQ(grains, r.grains) << "the " << preset << " grains changed (fingerprint 0x" << std::hex << grains
                              << "): measure the record again as above";
  const auto taken = embedded_index_densities(spec);
  ASSERT_TRUE(taken);
  EXPECT_EQ(taken->e_max, r.e_max);
  EXPECT_GT(r.e_min, 0.3);
  EXPECT_GT(r.e_max, r.e_min + 0.1);
  EXPECT_LT(r.e_max, 1.0);
  const auto takes_this = [&](auto change) {
    LabSpec s = spec;
    change(s);
    const auto t = embedded_index_densities(s);
    return t && t->key_hash == r.key_hash;
  };
  for (const char* other : {"rounded", "sh-ottawa", "sh-river", "sh-limestone"})
    if (other != preset) {
      EXPECT_FALSE(takes_this([&](LabSpec& s) { s.grains.preset = other; })) << other;
    }
  EXPECT_FALSE(takes_this([](LabSpec& s) { s.grains.faces = 1000; }));
  EXPECT_FALSE(takes_this([](LabSpec& s) { s.seed = 2; }));
  EXPECT_FALSE(takes_this([](LabSpec& s) { s.numerics.time_step_fraction = 0.2; }));
}

}  // namespace

TEST(EmbeddedIndices, BelongToTheShOttawaPresetAndItsGrains) {
  expect_sh_preset_record("sh-ottawa", sh_ottawa_indices());
}

TEST(EmbeddedIndices, BelongToTheShRiverPresetAndItsGrains) {
  expect_sh_preset_record("sh-river", sh_river_indices());
}
