// `grainlab run FILE`: a lab test (direct shear, oedometer, triaxial) from a
// TOML config. The run itself is run_lab (apps/run_lab.h); this command reads
// the options, prints the run's lines on standard output and turns
// SIGINT/SIGTERM/SIGHUP/SIGXFSZ into a checkpoint and exit code 130.
#include "apps/commands.h"
#include "apps/run_lab.h"
#include "core/error.h"
#include "io/config.h"
#include "io/config_reference.h"
#include "lab/lab_test.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <atomic>
#include <csignal>
#include <cstdio>
#include <memory>
#include <string_view>

namespace grainlab::apps {

namespace {

std::atomic<int> g_stop_signal{0};
extern "C" void on_stop_signal(int sig) { g_stop_signal = sig; }

struct RunOptions {
  std::string file;
  bool print_defaults = false;
  bool print_reference = false;
  bool use_defaults = false;
  bool resume = false;
  bool quiet = false;
  bool no_report = false;
  std::string test;                   // for --print-defaults and --default ("": the spec's default test)
  std::string law;                    // the same; "" = the default law
  int threads = -1;                   // --threads: numerics.threads of the run (-1: the file's)
};

int run(const RunOptions& o) {
  const ContactLaw law = o.law.empty() ? ContactLaw{} : parse_contact_law(o.law);
  if (o.print_defaults) {
    fmt::print("{}", default_config_toml(o.test.empty() ? LabSpec{}.test : o.test, law));
    return 0;
  }
  if (o.print_reference) {
    fmt::print("{}", config_reference_markdown());
    return 0;
  }
  if (o.file.empty() && !o.use_defaults)
    input_error("grainlab run needs a config file (grainlab run test.toml), or --default for the "
                "embedded default; `grainlab run --print-defaults > test.toml` writes one to edit");
  if (!o.file.empty() && !o.test.empty() && o.test != LabSpec{}.test)
    input_error("--test {} chooses the test of --default and --print-defaults; a config file names its own "
                "(its top-level key test = \"{}\")",
                o.test, o.test);
  if (!o.file.empty() && !o.law.empty())
    input_error("--law {} chooses the contact law of --default and --print-defaults; a config file names its own "
                "(material.contact_law = \"{}\")",
                o.law, o.law);
  const LabSpec spec = o.use_defaults
                           ? parse_config(default_config_toml(o.test.empty() ? LabSpec{}.test : o.test, law),
                                          "<embedded default>")
                           : load_config(o.file);
  RunHooks hooks;
  hooks.say = [](std::string_view line) {
    fmt::print("{}\n", line);
    std::fflush(stdout);
  };
  hooks.stop_reason = [] {
    const int sig = g_stop_signal;
    return sig != 0 ? fmt::format("signal {}", sig) : std::string();
  };
  hooks.status_lines = !o.quiet;
  hooks.report = !o.no_report;
  hooks.resume_hint = fmt::format("`grainlab run {} --resume`", o.use_defaults ? "--default" : o.file);
  // A stop signal checkpoints and stops the run (while the specimen is
  // prepared: keeps the preparation in progress). A hang-up (the terminal
  // closed) and the file-size limit stop the run the same way (SIGXFSZ's
  // default would kill it unsaved; handled, the write that crossed the limit
  // fails with EFBIG instead). Installed once the config is read: a refused
  // config leaves the signals alone.
  for (const int sig : {SIGINT, SIGTERM, SIGHUP, SIGXFSZ}) std::signal(sig, on_stop_signal);
  return run_lab(spec, o.resume, o.threads, hooks);
}

}  // namespace

Command add_run_command(CLI::App& app) {
  auto o = std::make_shared<RunOptions>();
  auto* cmd = app.add_subcommand(
      "run",
      "run a virtual lab test from a TOML config: prepare a specimen at the target density, "
      "consolidate under the servo-held normal stress, then shear it to the final strain (test = "
      "\"direct-shear\"), hold each stress of a loading schedule in a rigid ring (test = \"oedometer\"), or "
      "compress it axially between walls servo-held at the cell pressure (test = \"triaxial\"). "
      "Writes series.csv "
      "(one row per strain interval, SI units, with rotation, coordination, fabric and shear-band columns), "
      "run.json (inputs, achieved density, peaks, Love-Weber stress), checkpoint.bin, analysis/ (final "
      "displacement profile, shear band, fabric, force chains), paraview/ (grains, contacts and walls every "
      "output.snapshot_interval of shear strain) and report/index.html to output.folder");
  cmd->add_option("file", o->file, "config file (TOML); see --print-defaults for every key with its unit");
  cmd->add_flag("--print-defaults", o->print_defaults, "print a complete, commented default config and exit");
  cmd->add_flag("--print-reference", o->print_reference,
                "print every config key of every test (table, default, unit, meaning) as Markdown and exit: "
                "docs/config.md");
  cmd->add_flag("--default", o->use_defaults, "run the embedded default (a small box of rounded grains, Ottawa-like)");
  cmd->add_option("--test", o->test,
                  fmt::format("the test of --default and --print-defaults: {} (default {})",
                              fmt::join(lab_test_names(), ", "), LabSpec{}.test))
      ->check(CLI::IsMember(lab_test_names()));
  cmd->add_option("--threads", o->threads,
                  "the run's worker threads: sets numerics.threads, overriding the config file's (0 = automatic: "
                  "up to all cores, the fastest count timed as it runs; the bits are the same on any count)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--law", o->law,
                  fmt::format("the contact law of --default and --print-defaults (which shows its parameters): {}",
                              contact_law_names()));
  cmd->add_flag("--resume", o->resume, "continue from output.folder/checkpoint.bin (same config)");
  cmd->add_flag("--quiet", o->quiet, "no progress lines");
  cmd->add_flag("--no-report", o->no_report, "skip the HTML report at the end (write it later with grainlab report)");
  return [cmd, o]() { return *cmd ? run(*o) : -1; };
}

}  // namespace grainlab::apps
