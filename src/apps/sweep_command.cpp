// `grainlab sweep SWEEP.toml [--scheduler ADDRESS] [--workers N] [--out DIR] [--dry-run]`:
// a parameter sweep on Dask. The sweep itself is Python (python/grainlab/sweep.py,
// on python3-distributed): this command replaces itself with
// `PYTHON -m grainlab._sweep_main SWEEP.toml --grainlab THIS_BINARY ...`, the package's
// folder put first on PYTHONPATH, so that every case runs this same binary. PYTHON is
// $GRAINLAB_PYTHON or /usr/bin/python3; the package is found next to the binary
// (build/python) or in the source tree it was built from. The Python side reads and
// checks the sweep file and says what to install when Dask is missing.
#include "apps/commands.h"
#include "core/error.h"

#include <fmt/format.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <unistd.h>

#ifndef GRAINLAB_PYTHON_SOURCE_DIR
#define GRAINLAB_PYTHON_SOURCE_DIR ""
#endif

namespace grainlab::apps {

namespace {

namespace fs = std::filesystem;

struct SweepOptions {
  std::string file;
  std::string scheduler;
  int workers = 0;
  std::string out;
  bool dry_run = false;
};

fs::path this_binary() {
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  if (ec) throw RunError(fmt::format("cannot find this program's own path (/proc/self/exe): {}", ec.message()));
  return self;
}

// The folder holding grainlab/sweep.py: next to the binary (build/python), else the source tree's.
fs::path package_folder(const fs::path& binary) {
  std::vector<fs::path> candidates = {binary.parent_path() / "python"};
  if (const std::string source = GRAINLAB_PYTHON_SOURCE_DIR; !source.empty()) candidates.emplace_back(source);
  std::string looked;
  for (const fs::path& c : candidates) {
    if (fs::exists(c / "grainlab" / "sweep.py")) return c;
    looked += (looked.empty() ? "'" : ", '") + c.string() + "'";
  }
  throw RunError(fmt::format("the Python package of grainlab sweep (grainlab/sweep.py) is in none of {}: "
                             "build grainlab from its source tree, or copy its python/ folder next to the binary",
                             looked));
}

int run_sweep(const SweepOptions& o) {
  const fs::path binary = this_binary();
  const fs::path package = package_folder(binary);
  const char* forced = std::getenv("GRAINLAB_PYTHON");
  const std::string python = forced && *forced ? forced : "/usr/bin/python3";
  std::vector<std::string> args = {python, "-m", "grainlab._sweep_main", o.file, "--grainlab", binary.string()};
  if (!o.scheduler.empty()) args.insert(args.end(), {"--scheduler", o.scheduler});
  if (o.workers > 0) args.insert(args.end(), {"--workers", std::to_string(o.workers)});
  if (!o.out.empty()) args.insert(args.end(), {"--out", o.out});
  if (o.dry_run) args.emplace_back("--dry-run");
  const char* old = std::getenv("PYTHONPATH");
  const std::string path = package.string() + (old && *old ? ":" + std::string(old) : std::string());
  setenv("PYTHONPATH", path.c_str(), 1);
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::fflush(stdout);
  std::fflush(stderr);
  execv(python.c_str(), argv.data());
  const int err = errno;
  throw RunError(fmt::format("cannot start '{}' for the sweep: {}; install Python 3 with Dask (`sudo apt-get "
                             "install python3 python3-distributed`), or point GRAINLAB_PYTHON at a python3 that "
                             "imports distributed",
                             python, std::strerror(err)));
}

}  // namespace

Command add_sweep_command(CLI::App& app) {
  auto o = std::make_shared<SweepOptions>();
  auto* cmd = app.add_subcommand(
      "sweep",
      "run a parameter sweep: every case (a base config with values from a grid, crossed with seeds) is one "
      "`grainlab run` in its own folder, scheduled on Dask (python3-distributed): a local cluster of one "
      "single-threaded worker per core, or an existing cluster (--scheduler). Finished cases are skipped, so the "
      "same command continues a stopped sweep; a case whose worker dies continues from its checkpoint; a failing "
      "case is reported and the others go on. Writes OUT/CASE/ (each run's files), OUT/cases.csv (every case's "
      "inputs and results, SI units as the column names say) and OUT/report/index.html (the comparison). The "
      "sweep file: docs/sweeps.md; `grainlab sweep SWEEP.toml --dry-run` lists its cases");
  cmd->add_option("sweep_file", o->file,
                  "the sweep file (TOML): base = \"base.toml\" or an inline [base] config, seeds = [...], and a "
                  "[grid] of \"dotted.config_key\" = [values]")
      ->required();
  cmd->add_option("--scheduler", o->scheduler,
                  "a running Dask scheduler: its address (e.g. tcp://head:8786) or the file of `dask scheduler "
                  "--scheduler-file FILE`; start workers with `dask worker ADDRESS --nthreads 1` (docs/sweeps.md). "
                  "Default: a local cluster");
  cmd->add_option("--workers", o->workers, "worker processes of the local cluster (default: one per core)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--out", o->out, "the sweep's folder (default: the file's out, else runs/<file name>)");
  cmd->add_flag("--dry-run", o->dry_run, "list the cases and which of them finished before; run nothing");
  return [cmd, o]() { return *cmd ? run_sweep(*o) : -1; };
}

}  // namespace grainlab::apps
