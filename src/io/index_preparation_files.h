// A preparation of the index box in progress, kept in the run folder as a
// checkpoint file (io/checkpoint.h) per preparation:
// index_e_min_seed7.bin, index_e_max_seed7.bin. A run stopped or killed
// while it measures the grains' own index densities goes on from the last
// one when started again (lab/index_densities.h, IndexPreparationStore).
//
// The checkpoint's key (its config_hash field) is a hash of what the
// preparation depends on: index_cache_key of the preparation's spec (seed,
// grains, material, stress, numerics but threads) plus its box and
// deposition friction. Its protocol bytes are the wall seconds spent so far
// (f64) followed by the DirectShearTest's own bytes. A file with another key
// is left alone and written over by the next keep.
#pragma once

#include "lab/index_densities.h"

#include <filesystem>
#include <functional>

namespace grainlab {

class IndexPreparationFiles final : public IndexPreparationStore {
 public:
  // Files in `folder`; `stop` (may be empty) says when to stop.
  IndexPreparationFiles(std::filesystem::path folder, std::function<bool()> stop = {});

  double restore(DirectShearTest& test, const DirectShearSpec& prepared) override;
  void keep(const DirectShearTest& test, const DirectShearSpec& prepared, double wall_s) override;
  void drop(const DirectShearSpec& prepared) override;
  bool stop_requested() const override { return stop_ && stop_(); }

  // The file of a preparation.
  std::filesystem::path file(const DirectShearSpec& prepared) const;

 private:
  std::filesystem::path folder_;
  std::function<bool()> stop_;
};

// The key above.
std::uint64_t index_preparation_key(const DirectShearSpec& prepared);

}  // namespace grainlab
