// `grainlab report RUN_DIR [RUN_DIR ...] [--out DIR]`: the HTML report of one
// run, or a comparison of several, by the Python package grainlab.report
// (python/grainlab/report/). The package is compiled into the binary
// (cmake/embed_files.cmake), written to a temporary folder and run with a
// Python that has matplotlib and numpy (report.h). Several triaxial runs first
// get their Mohr-Coulomb fit written next to the comparison
// (io/mohr_coulomb_file.h), which the report draws.
#include "apps/commands.h"
#include "apps/report.h"
#include "core/error.h"
#include "io/mohr_coulomb_file.h"

#include <fmt/format.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <system_error>
#include <vector>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace grainlab::apps {

namespace {

// Runs argv[0] (looked up in PATH when it has no '/') and waits; its output
// goes to ours, or nowhere when quiet. Exit status, or -1 if it could not start.
int spawn_and_wait(const std::vector<std::string>& args, bool quiet) {
  std::vector<std::string> copy = args;
  std::vector<char*> argv;
  for (std::string& a : copy) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  if (quiet) {
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_adddup2(&actions, 1, 2);
  }
  std::fflush(stdout);
  std::fflush(stderr);
  pid_t pid = -1;
  const int rc = posix_spawnp(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0) return -1;
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) return -1;
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

bool has_matplotlib(const std::string& python) {
  return spawn_and_wait({python, "-c", "import matplotlib, numpy"}, true) == 0;
}

// A temporary folder, removed with everything in it when this goes out of scope.
struct TempFolder {
  std::filesystem::path path;
  TempFolder() {
    std::string pattern = (std::filesystem::temp_directory_path() / "grainlab-report-XXXXXX").string();
    if (!mkdtemp(pattern.data()))
      throw RunError(fmt::format("cannot create a temporary folder like '{}' for the report's package: {}", pattern,
                                 std::strerror(errno)));
    path = pattern;
  }
  ~TempFolder() {
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
  }
};

struct ReportOptions {
  std::vector<std::string> runs;
  std::string out;
  std::string write_package;
};

// grainlab/__init__.py of the package written out: the report needs nothing
// else of grainlab (whose own __init__ loads the compiled module).
constexpr const char* kPackageInit =
    "\"\"\"grainlab.report alone, as `grainlab report` writes it out (the report's package, Python\n"
    "source): run `python3 -m grainlab.report RUN_DIR [--out DIR]` with this folder's parent on\n"
    "PYTHONPATH. The rest of the grainlab package (import grainlab: build/python) is not here.\"\"\"\n";

// Runs `python -m grainlab.report ARGS` from the package in `root`, put first
// on sys.path (before the working folder, which might hold another grainlab).
constexpr const char* kLauncher =
    "import runpy, sys\n"
    "sys.dont_write_bytecode = True\n"
    "sys.path.insert(0, sys.argv.pop(1))\n"
    "runpy.run_module('grainlab.report', run_name='__main__', alter_sys=True)\n";

}  // namespace

std::optional<std::string> report_python() {
  if (const char* forced = std::getenv("GRAINLAB_PYTHON"); forced && *forced)
    return has_matplotlib(forced) ? std::optional<std::string>(forced) : std::nullopt;
  for (const char* candidate : {"/usr/bin/python3", "python3"}) {
    if (candidate[0] == '/' && access(candidate, X_OK) != 0) continue;
    if (has_matplotlib(candidate)) return std::string(candidate);
  }
  return std::nullopt;
}

std::string missing_matplotlib_message() {
  const char* forced = std::getenv("GRAINLAB_PYTHON");
  const std::string which =
      forced && *forced ? fmt::format("$GRAINLAB_PYTHON ('{}') does not import them (or does not run)", forced)
                        : std::string("neither /usr/bin/python3 nor python3 on PATH imports them");
  return fmt::format(
      "the report needs Python 3 with matplotlib and numpy, and {}. Install them with "
      "`sudo apt-get install python3-matplotlib` (scripts/setup.sh does), or point GRAINLAB_PYTHON at a "
      "python3 that has them",
      which);
}

void write_report_package(const std::filesystem::path& dir) {
  std::vector<std::pair<std::string, std::string>> files = report_package_files();
  files.emplace_back("grainlab/__init__.py", kPackageInit);
  for (const auto& [name, text] : files) {
    const std::filesystem::path path = dir / name;
    std::error_code ec;
    std::filesystem::create_directories(path.parent_path(), ec);
    std::ofstream f(path, std::ios::binary);
    f << text;
    if (ec || !f.flush())
      throw RunError(fmt::format("cannot write the report's package file '{}': check that {} is writable and has "
                                 "space", path.string(), dir.string()));
  }
}

std::string prepare_report_folder(const std::vector<std::string>& run_dirs, const std::string& out) {
  const std::vector<std::filesystem::path> folders(run_dirs.begin(), run_dirs.end());
  if (!is_triaxial_comparison(folders)) return out;
  // The report's default folder for a comparison: RUN_A/../comparison/report.
  const std::string out_dir =
      out.empty() ? (std::filesystem::canonical(folders.front()).parent_path() / "comparison" / "report").string()
                  : out;
  write_mohr_coulomb_file(folders, out_dir);
  return out_dir;
}

int run_report(const std::vector<std::string>& run_dirs, const std::string& out) {
  const std::optional<std::string> python = report_python();
  if (!python) {
    fmt::print(stderr, "grainlab report: {}\n", missing_matplotlib_message());
    return -1;
  }
  const TempFolder tmp;
  write_report_package(tmp.path);
  std::vector<std::string> args = {*python, "-c", kLauncher, tmp.path.string()};
  args.insert(args.end(), run_dirs.begin(), run_dirs.end());
  const std::string out_dir = prepare_report_folder(run_dirs, out);
  if (!out_dir.empty()) args.insert(args.end(), {"--out", out_dir});
  const int rc = spawn_and_wait(args, false);
  if (rc < 0) throw RunError(fmt::format("could not start '{}' to run the report", *python));
  return rc;
}

Command add_report_command(CLI::App& app) {
  auto o = std::make_shared<ReportOptions>();
  auto* cmd = app.add_subcommand(
      "report",
      "write the HTML report of a run folder (RUN_DIR/report/index.html: stress ratio, dilation, displacement "
      "profile and shear band, rotation, coordination, contact-normal rose diagrams with Kanatani's density, "
      "fabric factor, force chains; paper Figs. 10-17), or with several run folders a comparison report "
      "(RUN_A/../comparison/report/index.html); several triaxial runs at different sigma_3 give Mohr circles "
      "and a c', phi' fit (also in mohr_coulomb.json). Needs Python 3 with matplotlib (python3-matplotlib)");
  cmd->add_option("runs", o->runs, "run folder(s) written by `grainlab run` (series.csv, run.json, analysis/)");
  cmd->add_option("--out", o->out, "folder for index.html and the PNGs instead of the default");
  cmd->add_option("--write-package", o->write_package,
                  "write the report's Python package, as compiled into this binary, to DIR/grainlab/report/*.py "
                  "(and a DIR/grainlab/__init__.py) and exit; run it with `PYTHONPATH=DIR python3 -m "
                  "grainlab.report RUN_DIR [--out DIR]`, to read or change the figures")
      ->type_name("DIR");
  return [cmd, o]() -> int {
    if (!*cmd) return -1;
    if (!o->write_package.empty()) {
      write_report_package(o->write_package);
      fmt::print("wrote the package grainlab.report ({} files) to {}\n", report_package_files().size(),
                 (std::filesystem::path(o->write_package) / "grainlab" / "report").string());
      return 0;
    }
    if (o->runs.empty())
      input_error("grainlab report needs at least one run folder: grainlab report RUN_DIR [RUN_DIR ...] [--out DIR]");
    const int rc = run_report(o->runs, o->out);
    return rc < 0 ? 1 : rc;
  };
}

}  // namespace grainlab::apps
