// Shared helpers of the apps tests: run a shell command line or this build's
// grainlab binary, read a file.
#pragma once

#include "file_text.h"

#include <cstdio>
#include <filesystem>
#include <string>

#include <sys/wait.h>

namespace apps_test {

struct Result {
  int exit_code;
  std::string output;
};

// Runs `command` in /bin/sh, capturing stdout and stderr together.
inline Result run_shell(const std::string& command) {
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  std::string out;
  char buf[4096];
  while (pipe && std::fgets(buf, sizeof(buf), pipe)) out += buf;
  const int status = pipe ? pclose(pipe) : -1;
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out};
}

// Runs this build's `grainlab ARGS` (GRAINLAB_BINARY) in folder `cwd`, as a
// user would, with `env` (e.g. "OMP_NUM_THREADS=1") before it.
inline Result run_grainlab(const std::filesystem::path& cwd, const std::string& args, const std::string& env = "") {
  return run_shell("cd '" + cwd.string() + "' && " + env + " '" + GRAINLAB_BINARY + "' " + args);
}

inline std::string read_file(const std::filesystem::path& p) { return grainlab::test::file_text(p); }

}  // namespace apps_test
