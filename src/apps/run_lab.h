// One lab test run from a config, as `grainlab run` does it: checks, the
// folder's lock, preparation, the step loop with its checkpoints, series.csv,
// run.json, analysis/, paraview/ and the report. The command line
// (run_command.cpp) and the Python module (src/python/module.cpp) both call
// run_lab; they differ only in their hooks: where the lines go, what asks the
// run to stop (a signal, a KeyboardInterrupt) and who watches its progress.
#pragma once

#include "lab/lab_spec.h"

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>

namespace grainlab::apps {

// Where a run stands, after each chunk of steps (about four a second).
struct RunProgress {
  std::string phase;           // the test's phase name
  std::int64_t step = 0;       // steps since the run began (a resumed run counts on)
  double time_s = 0;           // simulated time (s)
  bool loading = false;        // in the loading phase (shear, compression, stages)
  double progress = 0;         // loading progress (direct shear: shear strain), 0 before loading
  double final_progress = 1;   // where loading ends
  std::string progress_label;  // what progress measures ("shear strain")
  std::string status;          // one line of current measurements
};

struct RunHooks {
  // Each line the run reports (header, phases, progress lines, the result);
  // the command line prints them on standard output.
  std::function<void(std::string_view)> say = [](std::string_view) {};
  // Asked after each chunk of steps: "" goes on; anything else (e.g. "signal
  // 15") saves a checkpoint and stops the run, which returns 130. Once it
  // answered a reason it must keep answering one.
  std::function<std::string()> stop_reason = [] { return std::string(); };
  // Called after each chunk of steps.
  std::function<void(const RunProgress&)> progress;
  bool status_lines = true;  // the "[phase] step ..." line every 2 s (--quiet: false)
  bool report = true;        // the HTML report at the end (--no-report: false)
  // How to go on after a stop, for the messages: "`grainlab run test.toml --resume`".
  std::string resume_hint;
};

// Runs `spec` into spec.output.folder; `resume` goes on from its checkpoint.
// `threads` >= 0 overrides numerics.threads (the bits do not depend on it).
// Returns 0 when the run finished, 130 when stop_reason stopped it (a
// checkpoint, or the preparation in progress, kept). Bad input: InputError
// before anything is written; a failed write: WriteError naming the last
// checkpoint.
int run_lab(LabSpec spec, bool resume, int threads, const RunHooks& hooks);

}  // namespace grainlab::apps
