// The grainlab command line as an object: every subcommand registered on one
// CLI11 app. main() parses argv with it and turns exceptions into exit codes;
// the Python module (src/python/module.cpp) parses an argument list with it
// and lets them become Python exceptions, so that grainlab.grains and
// grainlab.ct run exactly the subcommands a shell runs.
#pragma once

#include "apps/commands.h"

#include <CLI/CLI.hpp>

#include <vector>

namespace grainlab::apps {

class CommandLine {
 public:
  CommandLine();
  CommandLine(const CommandLine&) = delete;
  CommandLine& operator=(const CommandLine&) = delete;

  CLI::App app;  // parse the arguments with this (app.parse), then run()

  // Runs the subcommand that parsing chose; its exit code. Exceptions (InputError, RunError, ...) pass through.
  int run() const;

 private:
  std::vector<Command> commands_;
};

}  // namespace grainlab::apps
