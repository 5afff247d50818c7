// Preparations in progress kept in the run folder as checkpoint files
// (io/checkpoint.h), one per preparation, named as lab/preparation_store.h
// names them: index_e_min_seed7.bin, index_e_max_seed7.bin (the grains' own
// index densities), trial_friction_0.02990000.bin (a trial of the search
// for the deposition friction). A run stopped or killed while it prepares
// goes on from them when started again.
//
// A file's key (its config_hash field) is a hash of what the preparation
// depends on: for an index preparation, index_cache_key of its spec (seed,
// grains, material, stress, numerics but threads) plus its box and
// deposition friction; for a trial, the whole config but the output, the
// thread count and the loading (every lab test's own table). Its protocol
// bytes are the wall seconds spent so far (f64) followed by the
// SpecimenPreparation's own bytes (lab/preparation.h). A file with another key, or written for
// other grains (checkpoint.h, grains_fingerprint), is left alone and
// written over by the next keep.
//
// Index preparations are dropped once index_densities.json holds them;
// trials stay (finished ones at their end: the search takes them back at
// once) until the run writes its first checkpoint (drop_kept_trials).
#pragma once

#include "lab/preparation_store.h"

#include <filesystem>
#include <functional>

namespace grainlab {

class KeptPreparations final : public PreparationStore {
 public:
  // Files in `folder`; `stop` (may be empty) says when to stop.
  explicit KeptPreparations(std::filesystem::path folder, std::function<bool()> stop = {});

  double restore(SpecimenPreparation& preparation, const std::string& name, const LabSpec& prepared) override;
  void keep(const SpecimenPreparation& preparation, const std::string& name, const LabSpec& prepared,
            double wall_s) override;
  void drop(const std::string& name) override;
  bool stop_requested() const override { return stop_ && stop_(); }

  // The file of a preparation.
  std::filesystem::path file(const std::string& name) const;

 private:
  std::filesystem::path folder_;
  std::function<bool()> stop_;
};

// The key above.
std::uint64_t kept_preparation_key(const std::string& name, const LabSpec& prepared);

// Whether a file name is that of a kept preparation (index_e_min_seed7.bin,
// trial_friction_0.02990000.bin); `trials_only`: of a trial.
bool is_kept_preparation_file(const std::string& filename, bool trials_only = false);

// Removes the kept trials (trial_*.bin) from `folder`.
void drop_kept_trials(const std::filesystem::path& folder);

}  // namespace grainlab
