// grainlab: the command line. Each subcommand lives in its own *_command.cpp
// and explains itself with --help.
#include "apps/commands.h"
#include "core/error.h"
#include "core/wait_policy.h"

#include <fmt/format.h>

#include <vector>

using namespace grainlab;

int main(int argc, char** argv) {
  use_passive_wait_by_default(argv);
  CLI::App app{
      "grainlab: a discrete-element engine and virtual soil laboratory for realistic sand "
      "grains.\nSI units throughout (m, kg, s, N, Pa)."};
  app.require_subcommand(1);

  const std::vector<apps::Command> commands = {apps::add_grains_command(app),
                                               apps::add_run_command(app), apps::add_report_command(app),
                                               apps::add_ct_command(app)};

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  try {
    for (const auto& run : commands) {
      const int rc = run();
      if (rc >= 0) return rc;
    }
  } catch (const InputError& e) {
    fmt::print(stderr, "grainlab: error: {}\n", e.what());
    return 2;
  } catch (const RunError& e) {
    fmt::print(stderr, "grainlab: run failed: {}\n", e.what());
    return 3;
  }
  return 0;
}
