// Steps per second of the real preparation workload: a kept index
// preparation (output.folder/index_e_min_seed7.bin, written while a run
// measures the grains' own index densities; io/kept_preparations.h) or a
// kept trial of the friction search (trial_friction_0.01000000.bin, with the
// run's index_densities.json beside it) loaded into its test and stepped, so that a change to the contact code is
// timed on the grains and the packing that made it slow, and its bits
// compared (the checksum of the final poses and velocities).
//   build/bench_kept_preparation CONFIG KEPT_FILE [--steps N] [--threads T] [--repeat R]
// e.g. build/bench_kept_preparation bench/results/study_four_sands/configs/angular.toml
//        bench/results/study_four_sands/angular/index_e_min_seed7.bin --steps 20 --threads 1
//      build/bench_kept_preparation bench/results/study_four_sands/configs/angular.toml
//        bench/results/study_four_sands/angular/trial_friction_0.01000000.bin --steps 20
// Prints steps/s per repeat (each from the same kept state) and their median.
#include "bench_args.h"
#include "core/bytes.h"
#include "core/timer.h"
#include "io/checkpoint.h"
#include "io/config.h"
#include "io/kept_preparations.h"
#include "io/preparation_files.h"
#include "lab/index_densities.h"
#include "lab/preparation.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <regex>
#include <string>
#include <vector>

using namespace grainlab;

int main(int argc, char** argv) {
  grainlab::bench::check_args(argc, argv, "CONFIG KEPT_FILE [--steps N] [--threads T] [--repeat R]",
                              {"--steps", "--threads", "--repeat"}, {}, 3);
  if (argc < 3) {
    fmt::print(stderr, "usage: {} CONFIG KEPT_FILE [--steps N] [--threads T] [--repeat R]\n", argv[0]);
    return 2;
  }
  int steps = 20, threads = 1, repeat = 3;
  for (int i = 3; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--steps")) steps = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--threads")) threads = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--repeat")) repeat = std::atoi(argv[i + 1]);
  }
  const std::string kept = argv[2];
  std::smatch m;
  const std::string name = std::filesystem::path(kept).filename().string();
  LabSpec prepared = load_config(argv[1]);
  if (std::regex_match(name, m, std::regex(R"(index_e_(min|max)_seed(\d+)\.bin)"))) {
    prepared = index_preparation_spec(prepared, IndexDensityOptions{}, m[1] == "min", std::stoull(m[2].str()));
  } else if (std::regex_match(name, m, std::regex(R"(trial_friction_([0-9.]+)\.bin)"))) {
    // A trial: the run's spec with the own indices it measured, at the trial's friction.
    const auto indices = std::filesystem::path(kept).parent_path() / "index_densities.json";
    const auto own = cached_index_densities(indices, prepared);
    if (!own) {
      fmt::print(stderr, "{}: no finished index densities of this config beside the trial; the trial needs them\n",
                 indices.string());
      return 2;
    }
    prepared.specimen.own_e_min = own->first;
    prepared.specimen.own_e_max = own->second;
    // The name holds the friction to 8 decimals, the key its bits: the
    // double within 256 ulps of the name's whose key matches.
    double mu = std::stod(m[1].str());
    for (int i = 0; i < 256; ++i) mu = std::nextafter(mu, 0.0);
    const std::uint64_t key = load_checkpoint(kept).config_hash;
    for (int i = 0; i <= 512; ++i, mu = std::nextafter(mu, 1.0)) {
      prepared.specimen.deposition_friction = mu;
      if (kept_preparation_key(std::filesystem::path(kept).stem().string(), prepared) == key) break;
    }
  } else {
    fmt::print(stderr, "{}: expected a kept preparation named index_e_min_seedN.bin, index_e_max_seedN.bin or "
               "trial_friction_X.bin\n", kept);
    return 2;
  }
  const std::string stem = std::filesystem::path(kept).stem().string();
  if (load_checkpoint(kept).config_hash != kept_preparation_key(stem, prepared)) {
    fmt::print(stderr, "{} was not kept from {} (another key): give the config of the run that kept it\n", kept,
               argv[1]);
    return 2;
  }
  prepared.numerics.threads = threads;  // not part of the key
  std::vector<double> rates;
  for (int r = 0; r < repeat; ++r) {
    SpecimenPreparation t(prepared);
    t.accept_any_density();
    KeptPreparations files(std::filesystem::path(kept).parent_path());
    files.restore(t, stem, prepared);
    if (r == 0)
      fmt::print("{} grains, step {} ({} phase), {} contacts; {} steps on {} thread(s)\n", t.world().model.bodies.size(),
                 t.world().state.step, t.phase_name(), t.world().state.contacts.size(), steps, threads);
    Stopwatch clock;
    for (int i = 0; i < steps; ++i) t.world().step(t.time_step());
    rates.push_back(steps / clock.seconds());
    double sum = 0;
    for (const BodyState& b : t.world().state.bodies) sum += b.x.sum() + 1e-3 * b.v.sum() + 1e-6 * b.w.sum();
    fmt::print("  repeat {}: {:.3f} steps/s, checksum {:.17g}\n", r + 1, rates.back(), sum);
  }
  std::sort(rates.begin(), rates.end());
  fmt::print("median {:.3f} steps/s\n", rates[rates.size() / 2]);
}
