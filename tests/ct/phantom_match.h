// Segmented grains against a packed phantom's true labels (packed_phantom.h),
// by voxel overlap: a true grain is found one to one when exactly one
// segmented grain covers at least 10 % of it and that grain covers no 10 %
// of another true grain; two or more covering it: split; its one grain also
// covering another: merged. Volume errors (mesh volume over the true volume)
// are taken over the grains found one to one.
#pragma once

#include "ct/packed_phantom.h"
#include "ct/segmentation.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace grainlab::ct::testing {

struct PhantomScore {
  int truth = 0, one_to_one = 0, merged = 0, split = 0, lost = 0;
  std::vector<double> volume_errors;  // |V_seg / V_true - 1| of the one-to-one grains
  double median_error() const {
    if (volume_errors.empty()) return 0;
    std::vector<double> e = volume_errors;
    std::nth_element(e.begin(), e.begin() + e.size() / 2, e.end());
    return e[e.size() / 2];
  }
  double worst_error() const {
    return volume_errors.empty() ? 0 : *std::max_element(volume_errors.begin(), volume_errors.end());
  }
  PhantomScore& operator+=(const PhantomScore& o) {
    truth += o.truth, one_to_one += o.one_to_one, merged += o.merged, split += o.split, lost += o.lost;
    volume_errors.insert(volume_errors.end(), o.volume_errors.begin(), o.volume_errors.end());
    return *this;
  }
  std::string line() const {
    char b[200];
    std::snprintf(b, sizeof b, "%d/%d one to one, %d merged, %d split, %d lost; volume median %.1f %%, worst %.1f %%",
                  one_to_one, truth, merged, split, lost, 100 * median_error(), 100 * worst_error());
    return b;
  }
};

// `seg` must have been made with SegmentOptions::keep_labels.
inline PhantomScore score_phantom(const PackedPhantom& ph, const Segmentation& seg) {
  const int nt = static_cast<int>(ph.volumes.size()), ns = static_cast<int>(seg.grains.size());
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::int64_t> overlap;  // (true, segmented) -> voxels
  std::vector<std::int64_t> truth_voxels(nt + 1, 0);
  for (std::size_t i = 0; i < ph.truth.values.size(); ++i) {
    const std::uint32_t t = ph.truth.values[i];
    if (!t) continue;
    ++truth_voxels[t];
    if (const std::uint32_t s = seg.labels.values[i]) ++overlap[{t, s}];
  }
  std::vector<std::vector<int>> covering(nt + 1);  // true grain -> segmented grains covering 10 % of it
  std::vector<int> covers(ns + 1, 0);              // segmented grain -> true grains it covers 10 % of
  for (const auto& [key, count] : overlap) {
    if (count >= 0.1 * truth_voxels[key.first]) {
      covering[key.first].push_back(static_cast<int>(key.second));
      ++covers[key.second];
    }
  }
  PhantomScore score;
  score.truth = nt;
  for (int t = 1; t <= nt; ++t) {
    if (covering[t].empty()) {
      ++score.lost;
    } else if (covering[t].size() > 1) {
      ++score.split;
    } else if (covers[covering[t][0]] > 1) {
      ++score.merged;
    } else {
      ++score.one_to_one;
      const SegmentedGrain& g = seg.grains[covering[t][0] - 1];
      score.volume_errors.push_back(std::abs(g.volume / ph.volumes[t - 1] - 1));
    }
  }
  return score;
}

}  // namespace grainlab::ct::testing
