// Running the HTML report (scripts/report.py, compiled into the binary) from
// the command line: `grainlab report` and the end of `grainlab run`.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace grainlab::apps {

// The text of scripts/report.py as it was at build time (generated source,
// cmake/embed_text.cmake).
std::string report_script_text();

// The Python interpreter to run the report with: $GRAINLAB_PYTHON if set
// (and only it), else /usr/bin/python3 if it imports matplotlib and numpy,
// else `python3` from PATH if it does; nullopt when none does.
std::optional<std::string> report_python();

// What to tell a user whose Python lacks matplotlib (one paragraph).
std::string missing_matplotlib_message();

// Writes the script to a temporary file and runs it on `run_dirs` (with
// --out when `out` is not empty), its output going to this process's stdout
// and stderr. Returns the script's exit status (0: written; the script prints
// the path of index.html), or -1 with missing_matplotlib_message() on stderr
// when no Python with matplotlib is found. Throws RunError if the temporary
// file cannot be written or the interpreter cannot be started.
int run_report(const std::vector<std::string>& run_dirs, const std::string& out = "");

}  // namespace grainlab::apps
