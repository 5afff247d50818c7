// Runs the grainlab binary of this build (GRAINLAB_BINARY) as a user would,
// for the tests of the command line.
#pragma once

#include <cstdio>
#include <filesystem>
#include <string>

#include <sys/wait.h>

namespace grainlab::testing_support {

struct GrainlabResult {
  int exit_code;
  std::string output;  // stdout and stderr together
};

// Runs `grainlab ARGS` in folder `cwd`, with `env` (e.g. "OMP_NUM_THREADS=1") before it.
inline GrainlabResult run_grainlab(const std::filesystem::path& cwd, const std::string& args,
                                   const std::string& env = "") {
  const std::string cmd = "cd '" + cwd.string() + "' && " + env + " '" + GRAINLAB_BINARY + "' " + args + " 2>&1";
  FILE* pipe = popen(cmd.c_str(), "r");
  std::string out;
  char buf[4096];
  while (pipe && std::fgets(buf, sizeof(buf), pipe)) out += buf;
  const int status = pipe ? pclose(pipe) : -1;
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out};
}

}  // namespace grainlab::testing_support
