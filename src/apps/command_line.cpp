// CommandLine (apps/command_line.h): the app and its subcommands.
#include "apps/command_line.h"

namespace grainlab::apps {

CommandLine::CommandLine()
    : app("grainlab: a discrete-element engine and virtual soil laboratory for realistic sand "
          "grains.\nSI units throughout (m, kg, s, N, Pa).") {
  app.require_subcommand(1);
  commands_ = {add_grains_command(app), add_run_command(app), add_report_command(app), add_ct_command(app),
               add_sweep_command(app)};
}

int CommandLine::run() const {
  for (const auto& command : commands_) {
    const int rc = command();
    if (rc >= 0) return rc;
  }
  return 0;
}

}  // namespace grainlab::apps
