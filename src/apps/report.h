// Running the HTML report (the Python package grainlab.report, compiled into
// the binary) from the command line: `grainlab report` and the end of
// `grainlab run`.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace grainlab::apps {

// The files of the package grainlab.report as they were at build time:
// {"grainlab/report/NAME.py", text} for every python/grainlab/report/*.py
// (generated source, cmake/embed_files.cmake).
std::vector<std::pair<std::string, std::string>> report_package_files();

// Writes the package into `dir` as an importable tree: dir/grainlab/report/*.py
// and a dir/grainlab/__init__.py that holds nothing but a docstring (the rest
// of the grainlab package is not needed by the report), so that
// `PYTHONPATH=dir python3 -m grainlab.report RUN_DIR` runs it. Creates `dir`;
// throws RunError when a file cannot be written.
void write_report_package(const std::filesystem::path& dir);

// The report's output folder for `run_dirs` with --out `out` ("": the
// default), after writing what the engine computes for it: several triaxial
// runs get their Mohr-Coulomb fit, out/mohr_coulomb.json (io/mohr_coulomb_file.h),
// which the report draws; their default folder RUN_A/../comparison/report is
// then returned. Any other set of runs: `out` unchanged.
std::string prepare_report_folder(const std::vector<std::string>& run_dirs, const std::string& out);

// The Python interpreter to run the report with: $GRAINLAB_PYTHON if set
// (and only it), else /usr/bin/python3 if it imports matplotlib and numpy,
// else `python3` from PATH if it does; nullopt when none does.
std::optional<std::string> report_python();

// What to tell a user whose Python lacks matplotlib (one paragraph).
std::string missing_matplotlib_message();

// Writes the package to a temporary folder and runs `python3 -m
// grainlab.report` from it on `run_dirs` (with --out when `out` is not
// empty), its output going to this process's stdout and stderr. Returns the
// report's exit status (0: written; it prints the path of index.html), or -1
// with missing_matplotlib_message() on stderr when no Python with matplotlib
// is found. Throws RunError if the temporary folder cannot be written or the
// interpreter cannot be started.
int run_report(const std::vector<std::string>& run_dirs, const std::string& out = "");

}  // namespace grainlab::apps
