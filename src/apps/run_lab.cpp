// run_lab (apps/run_lab.h): the run of `grainlab run` and of grainlab.run()
// in Python. Progress, series.csv (with the analysis columns of
// io/shear_analysis.h) and run.json, ParaView snapshots in paraview/ during
// loading, the final analysis files in analysis/, checkpoints on an interval
// and when the hooks ask the run to stop, resume, and at the end the HTML
// report in report/. Every output file is written to a temporary name and
// renamed; one run at a time holds the output folder's lock
// (core/folder_lock.h); a write that fails (a full disk, the file-size limit)
// ends the run naming the last checkpoint, which is intact.
#include "apps/run_lab.h"

#include "apps/report.h"
#include "apps/run_preparation.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/folder_lock.h"
#include "core/step_pacer.h"
#include "core/thread_tuner.h"
#include "core/timer.h"
#include "io/analysis_files.h"
#include "io/checkpoint.h"
#include "io/config.h"
#include "io/json.h"
#include "io/kept_preparations.h"
#include "io/run_summary.h"
#include "io/shear_analysis.h"
#include "io/shear_snapshots.h"
#include "io/table.h"
#include "lab/lab_test.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>

namespace grainlab::apps {

namespace {

// The summary value named key (top level), 0 if the test has none.
double summary_value(const LabTest& test, const std::string& key) {
  for (const SummaryValue& v : test.summary())
    if (v.group.empty() && v.key == key) return v.value;
  return 0;
}

void write_series(const LabTest& test, const std::filesystem::path& out) {
  Table t;
  t.columns = test.series_columns();
  t.rows = test.series();
  write_file_atomically(out / "series.csv", t.to_csv());
}

void write_run_json(const LabTest& test, const std::filesystem::path& out, double wall_s,
                    const nlohmann::json& preparation) {
  const World& w = test.world();
  nlohmann::json j;
  j["grainlab_version"] = "0.1.0";
  j["config"] = spec_to_json(test.spec());
  j["seed"] = test.spec().seed;
  j["grains"] = w.model.bodies.size();
  j["time_step_s"] = test.time_step();
  j["density_scaling"] = w.model.density_scale;
  j["phase"] = test.phase_name();
  for (const SummaryValue& v : test.summary()) (v.group.empty() ? j : j[v.group])[v.key] = v.value;
  j["timings"] = {{"wall_s", wall_s}, {"steps", w.state.step}, {"simulated_s", w.state.time}};
  // steps this sitting ran on each count.
  nlohmann::json threads = {{"numerics_threads", w.settings.threads}};
  if (w.settings.threads <= 0) {
    const ThreadTuner& tuner = w.thread_tuner();
    threads["trials"] = tuner.trials();
    for (std::size_t k = 0; k < tuner.counts().size(); ++k)
      threads["steps_on"][std::to_string(tuner.counts()[k])] = tuner.steps_run()[k];
  }
  j["timings"]["threads"] = threads;
  add_micromechanics_summary(j, test);
  add_peak_verdicts(j, test);
  j["specimen_preparation"] = preparation;
  write_json_file(out / "run.json", j);
}

RunProgress progress_of(const LabTest& test) {
  const World& w = test.world();
  RunProgress p;
  p.phase = test.phase_name();
  p.step = w.state.step;
  p.time_s = w.state.time;
  p.loading = test.loading();
  p.progress = test.progress();
  p.final_progress = test.final_progress();
  p.progress_label = test.progress_label();
  p.status = test.status_line();
  return p;
}

int run_loop(const RunHooks& hooks, bool resume, const LabSpec& spec, const LabSpec& keyed, PreparedRun& prepared,
             const std::filesystem::path& out, std::string& last_checkpoint);

}  // namespace

int run_lab(LabSpec spec, bool resume, int threads, const RunHooks& hooks) {
  if (threads >= 0) spec.numerics.threads = threads;  // the caller's count overrides the config's

  // Everything that can refuse the run happens before anything is written
  // (but the own index densities, which are measured once and kept).
  const std::filesystem::path out = spec.output.folder;
  const std::filesystem::path checkpoint = out / "checkpoint.bin";
  // The checkpoints' key: the config the run started with (a resumed run may
  // set another thread count: the bits do not depend on it).
  LabSpec keyed = spec;
  if (resume) {
    if (!std::filesystem::exists(checkpoint))
      input_error("--resume: no checkpoint at '{}'; start the run without --resume", checkpoint.string());
    LabSpec before = load_config(out / "config.toml");
    keyed.numerics.threads = before.numerics.threads;
    if (threads >= 0) before.numerics.threads = threads;
    const auto diff = config_differences(before, spec);
    if (!diff.empty())
      input_error("--resume: the config differs from the run in '{}' ({}); resume with the same config "
                  "or start a new run in another output.folder",
                  out.string(), fmt::join(diff, ", "));
  }
  // One run at a time in a folder: a second one would mix its files with this one's.
  const FolderLock lock(out, "grainlab run");
  if (const int stale = remove_stale_temporaries(out))
    hooks.say(fmt::format("removed {} temporary file(s) that a killed run left in '{}'", stale, out.string()));
  // A stop request while the specimen is prepared keeps the preparation in
  // progress and stops.
  PreparedRun prepared;
  try {
    prepared = prepare_run(spec, out, resume, [&] { return !hooks.stop_reason().empty(); });
  } catch (const Stopped& e) {
    hooks.say(fmt::format("stopped by {} while preparing the specimen: {}; run the same command again to go on",
                          hooks.stop_reason(), e.what()));
    return 130;
  }
  LabTest& test = *prepared.test;
  observe_shear_analysis(test);  // the same on resume: the rows of both runs then match
  if (prepared.specimen) {  // another run's prepared specimen (specimen.from), checked by prepare_run
    test.world().state = std::move(prepared.specimen->state);
    test.load(prepared.specimen->protocol);
    hooks.say(fmt::format("starting from the specimen in {} at step {} ({} phase)", spec.specimen.from,
                          test.world().state.step, test.phase_name()));
  }
  if (resume) {
    Checkpoint ck = load_checkpoint(checkpoint);
    if (ck.config_hash != config_hash(keyed))
      input_error("--resume: checkpoint '{}' belongs to another config", checkpoint.string());
    if (!same_grains(ck, test.world().model))
      input_error("--resume: checkpoint '{}' was written for other grains than this grainlab makes from the same "
                  "config (its grain generator or mesh import changed since). Resume it with the grainlab that "
                  "wrote it, or start the run again without --resume",
                  checkpoint.string());
    test.world().state = std::move(ck.state);
    test.load(ck.protocol);
    hooks.say(fmt::format("resuming at step {} ({} phase, {} {:.4f})", test.world().state.step, test.phase_name(),
                          test.progress_label(), test.progress()));
  } else {
    std::filesystem::create_directories(out);
    write_file_atomically(out / "config.toml", to_toml(spec));
  }
  // The last checkpoint written whole, for the message of a write that fails.
  std::string last_checkpoint =
      resume ? fmt::format("'{}' (step {})", checkpoint.string(), test.world().state.step) : std::string();
  try {
    return run_loop(hooks, resume, spec, keyed, prepared, out, last_checkpoint);
  } catch (const WriteError& e) {
    throw WriteError(fmt::format(
        "{}. {}; every file written before is whole (each is written to a temporary name and renamed)", e.what(),
        last_checkpoint.empty() ? std::string("No checkpoint was written yet")
                                : fmt::format("The last checkpoint, {}, is intact: once the file can be written, "
                                              "continue with {}",
                                              last_checkpoint, hooks.resume_hint)));
  }
}

namespace {

// The loop of a run whose test is prepared (run_lab above did the checks).
int run_loop(const RunHooks& hooks, bool resume, const LabSpec& spec, const LabSpec& keyed, PreparedRun& prepared,
             const std::filesystem::path& out, std::string& last_checkpoint) {
  LabTest& test = *prepared.test;
  const std::filesystem::path checkpoint = out / "checkpoint.bin";
  ShearSnapshots snapshots(out, test, resume);
  if (!resume && prepared.specimen) snapshots.write_loading_start(test);
  const auto save = [&] {
    save_checkpoint(checkpoint, test.world().state, test.save(), config_hash(keyed),
                    grains_fingerprint(test.world().model));
    last_checkpoint = fmt::format("'{}' (step {})", checkpoint.string(), test.world().state.step);
    drop_kept_trials(out);  // the run goes on from its checkpoint now
  };

  const World& w = test.world();
  const double shear_speed = summary_value(test, "shear_speed_m_per_s");
  const std::string source = !spec.grains.scan.empty()     ? "scan " + spec.grains.scan
                             : !spec.grains.folder.empty() ? "folder " + spec.grains.folder
                                                           : spec.grains.preset + " preset";
  hooks.say(fmt::format("grainlab run: {}, {} grains ({}), box {:.1f} x {:.1f} x {:.1f} mm, {:.0f} kPa, "
                        "dt {:.3g} s, density scaling {:g}{}, {}",
                        spec.test, w.model.bodies.size(), source, spec.box.length * 1e3, spec.box.width * 1e3,
                        spec.box.height * 1e3, spec.consolidation.normal_stress * 1e-3, test.time_step(),
                        w.model.density_scale,
                        shear_speed > 0 ? fmt::format(", shear speed {:.3g} mm/s", shear_speed * 1e3) : "",
                        thread_count_label(w.settings.threads)));

  Stopwatch clock, since_checkpoint, since_line;
  std::size_t written_rows = test.series().size();
  int phase = test.phase_index();
  std::int64_t shear_start_step = test.loading_start_step(), steps_at_start = w.state.step;
  bool running = true;
  StepPacer pacer;  // a stop request is seen within about a quarter second
  while (running) {
    const std::int64_t before = w.state.step;
    running = test.advance(pacer.next());
    pacer.done(w.state.step - before);
    if (test.series().size() != written_rows) {
      write_series(test, out);
      written_rows = test.series().size();
    }
    snapshots.update(test);
    if (test.phase_index() != phase) {
      phase = test.phase_index();
      if (test.loading()) shear_start_step = w.state.step;
      // The prepared specimen, for runs that shear it otherwise (specimen.from).
      if (test.loading() && w.state.step == test.loading_start_step())
        save_checkpoint(out / "specimen.bin", w.state, test.save(), specimen_hash(spec), grains_fingerprint(w.model));
      if (const std::string note = test.phase_note(); !note.empty()) hooks.say(fmt::format("  {}", note));
      hooks.say(fmt::format("  phase {} from step {}", test.phase_name(), w.state.step));
    }
    if (hooks.status_lines && (since_line.seconds() > 2 || !running)) {
      since_line.reset();
      const double rate = (w.state.step - steps_at_start) / std::max(1e-9, clock.seconds());
      std::string eta = "";
      if (test.loading() && test.progress() > 0) {
        const double steps_per_strain = (w.state.step - shear_start_step) / test.progress();
        eta = fmt::format("  ETA {:.0f} s", (test.final_progress() - test.progress()) * steps_per_strain / rate);
      }
      hooks.say(fmt::format("  [{}] step {}  {}  {:.0f} steps/s{}", test.phase_name(), w.state.step,
                            test.status_line(), rate, eta));
    }
    if (hooks.progress) hooks.progress(progress_of(test));
    if (since_checkpoint.seconds() > spec.output.checkpoint_interval) {
      save();
      since_checkpoint.reset();
    }
    if (const std::string reason = hooks.stop_reason(); !reason.empty()) {
      save();
      hooks.say(fmt::format("stopped by {}: checkpoint saved in '{}'; continue with {}", reason, checkpoint.string(),
                            hooks.resume_hint));
      return 130;
    }
  }
  save();
  write_series(test, out);
  write_analysis_files(test, out);
  snapshots.finish(test);
  write_run_json(test, out, clock.seconds(), prepared.record);
  hooks.say(fmt::format("done in {:.0f} s: {}\noutputs in {}: series.csv, run.json, checkpoint.bin, analysis/, "
                        "paraview/ ({} snapshots: open grains.pvd, contacts.pvd, walls.pvd in ParaView)",
                        clock.seconds(), test.result_line(), out.string(),
                        snapshots.writer().grains().entries().size()));
  if (hooks.report) {
    // The series and run.json are written: a report that fails only warns.
    int rc = -1;
    try {
      rc = run_report({out.string()});
    } catch (const RunError& e) {
      fmt::print(stderr, "grainlab run: {}\n", e.what());
    }
    if (rc != 0)
      fmt::print(stderr, "grainlab run: warning: the HTML report was not written (see above); the run's files are "
                         "complete. Write it later with `grainlab report {}`\n",
                 out.string());
  }
  return 0;
}

}  // namespace

}  // namespace grainlab::apps
