// Own indices and deposition friction before a run (see run_preparation.h).
#include "apps/run_preparation.h"

#include "io/embedded_indices.h"
#include "io/json.h"
#include "io/kept_preparations.h"
#include "io/preparation_files.h"
#include "lab/index_densities.h"
#include "lab/lab_registry.h"
#include "lab/preparation_search.h"
#include "lab/specimen_budget.h"

#include <fmt/format.h>

#include <cstdio>

namespace grainlab::apps {

namespace fs = std::filesystem;

PreparedRun prepare_run(const LabSpec& spec, const fs::path& out, bool resume,
                        const std::function<bool()>& stop) {
  LabSpec r = spec;
  PreparedRun run;
  const fs::path record_file = out / "preparation.json";
  if (resume) {
    if (fs::exists(record_file)) {
      run.record = read_json_file(record_file);
      r.specimen.own_e_min = run.record.value("own_e_min", r.specimen.own_e_min);
      r.specimen.own_e_max = run.record.value("own_e_max", r.specimen.own_e_max);
      r.specimen.deposition_friction = run.record.value("deposition_friction", r.specimen.deposition_friction);
    }
    run.test = make_lab_test(r.test, r);
    return run;
  }
  if (!spec.specimen.from.empty()) {
    // Another run's prepared specimen: nothing to prepare here (run_lab
    // loads it); its preparation record, beside it, says how it was made.
    const fs::path from = spec.specimen.from;
    if (!fs::is_regular_file(from))
      input_error("specimen.from = '{}': no such file. Give the specimen.bin that a run wrote in its output "
                  "folder as its loading began (runs write it since 2026-12-02), or remove specimen.from to "
                  "prepare a specimen",
                  from.string());
    const fs::path source_record = from.parent_path() / "preparation.json";
    if (fs::exists(source_record)) {
      run.record = read_json_file(source_record);
      r.specimen.own_e_min = run.record.value("own_e_min", r.specimen.own_e_min);
      r.specimen.own_e_max = run.record.value("own_e_max", r.specimen.own_e_max);
      r.specimen.deposition_friction = run.record.value("deposition_friction", r.specimen.deposition_friction);
    }
    run.record["specimen_from"] = fs::absolute(from).string();
    run.test = make_lab_test(r.test, r);
    // The same grains, box, seed, test, stress and density scaling; the
    // material and the loading may differ (io/checkpoint.h, specimen_hash).
    run.specimen = load_checkpoint(from);
    if (run.specimen->config_hash != specimen_hash(spec))
      input_error("specimen.from = '{}': that specimen was prepared with other grains, box, seed, test, "
                  "consolidation stress or density scaling than this config's. Use the grains, box, seed, "
                  "test, consolidation.normal_stress and numerics.density_scaling of the run that wrote it "
                  "(its config.toml, beside it); the material and the loading may differ",
                  from.string());
    if (run.specimen->state.bodies.size() != run.test->world().state.bodies.size())
      input_error("specimen.from = '{}': it holds {} grains, this config places {}; use the config of the run "
                  "that wrote it",
                  from.string(), run.specimen->state.bodies.size(), run.test->world().state.bodies.size());
    if (!same_grains(*run.specimen, run.test->world().model))
      input_error("specimen.from = '{}': that specimen was prepared with other grains than this grainlab makes "
                  "from the same config (its grain generator or mesh import changed since). Prepare the "
                  "specimen again with this grainlab, or use the grainlab that wrote it",
                  from.string());
    fs::create_directories(out);
    write_json_file(record_file, run.record);
    return run;
  }
  if (!spec.grains.scan.empty()) {
    // A scanned specimen is consolidated as scanned: no index densities, no deposition friction.
    fmt::print("placing the grains of the scan {} where they were scanned, then consolidating\n", spec.grains.scan);
    run.test = make_lab_test(r.test, r);
    fs::create_directories(out);
    write_json_file(record_file, run.record);
    return run;
  }
  check_specimen_fits(spec);
  KeptPreparations store(out, stop);  // what a stopped or killed preparation goes on from
  store.keep_interval_s = spec.output.checkpoint_interval;
  const auto print = [](const std::string& line) {
    fmt::print("  {}\n", line);
    std::fflush(stdout);
  };
  if (r.specimen.indices == "own" && !r.own_indices_known()) {
    const fs::path cache = out / "index_densities.json";
    if (const auto known = embedded_index_densities(spec)) {
      r.specimen.own_e_min = known->e_min;
      r.specimen.own_e_max = known->e_max;
      fmt::print("own index void ratios of these grains, built in ({}): e_min {:.4f}, e_max {:.4f}\n", known->how,
                 r.specimen.own_e_min, r.specimen.own_e_max);
      run.record["index_densities_source"] = known->how;
    } else if (const auto cached = cached_index_densities(cache, spec)) {
      std::tie(r.specimen.own_e_min, r.specimen.own_e_max) = *cached;
      fmt::print("own index void ratios from {}: e_min {:.4f}, e_max {:.4f}\n", cache.string(), r.specimen.own_e_min,
                 r.specimen.own_e_max);
      run.record["index_densities_file"] = cache.string();
    } else {
      IndexDensityOptions options;
      options.seeds = 1;
      fmt::print("measuring the grains' own index void ratios (box {} d_max across, 1 seed; "
                 "`grainlab grains index` measures several seeds; set specimen.own_e_min/own_e_max to skip)\n",
                 options.box_diameters);
      IndexDensities done = unfinished_index_densities(cache, spec);
      if (!done.dense.empty())
        fmt::print("  keeping the {} preparation(s) an earlier run saved in {}\n",
                   done.dense.size() + done.loose.size(), cache.string());
      // The folder is made when a preparation is kept, not before: a config
      // that the index box refuses (a time step above the critical one) writes nothing.
      const IndexDensities d = measure_index_densities(
          spec, options, print, std::move(done),
          [&](const IndexDensities& so_far) {
            fs::create_directories(out);
            write_index_densities(cache, spec, so_far, false);
          },
          &store);
      write_index_densities(cache, spec, d);
      if (!d.settled())
        fmt::print("  warning: a preparation hit the step cap before it came to rest; the indices are what "
                   "it reached\n");
      r.specimen.own_e_min = d.e_min;
      r.specimen.own_e_max = d.e_max;
      run.record["index_densities"] = to_json(d);
    }
  }
  if (r.specimen.deposition_friction < 0) {
    fmt::print("choosing the deposition friction for the target ({}):\n",
               r.targets_own_indices()
                   ? fmt::format("Dr {:.2f} on the own indices e_min {:.4f}, e_max {:.4f}", r.specimen.relative_density,
                                 r.specimen.own_e_min, r.specimen.own_e_max)
                   : fmt::format("e {:.4f}", r.target_void_ratio()));
    PreparationSearchOptions search;
    search.store = &store;
    // The trials are the test's own preparation (its box), so that the one
    // that lands on the target is its specimen.
    Preparation p = prepare_to_target(lab_preparation_spec(r.test, r), search, print);
    r.specimen.deposition_friction = p.friction;
    run.record["trials"] = to_json(p.trials);
    run.test = make_lab_test(r.test, r, std::move(p.specimen));
    // (A registered test that cannot take the trial prepares its specimen again.)
    if (run.test->world().state.step == 0)
      fmt::print("preparing the {} specimen with deposition friction {:.4g}\n", r.test, p.friction);
  } else {
    run.test = make_lab_test(r.test, r);
  }
  run.record["own_e_min"] = r.specimen.own_e_min;
  run.record["own_e_max"] = r.specimen.own_e_max;
  run.record["deposition_friction"] = r.specimen.deposition_friction;
  fs::create_directories(out);
  write_json_file(record_file, run.record);
  return run;
}

}  // namespace grainlab::apps
