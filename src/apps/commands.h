// The grainlab subcommands. Each registers itself on the CLI11 app and returns
// a callback that runs it (exit code), so main() stays a dispatcher.
#pragma once

#include "grains/sh_grain.h"

#include <CLI/CLI.hpp>

#include <cstdint>
#include <functional>
#include <string>

namespace grainlab::apps {

using Command = std::function<int()>;

// `grainlab grains generate|stats`: synthetic grain sets and grain shape metrics.
Command add_grains_command(CLI::App& app);

// `grainlab grains index` (registered by add_grains_command on its `grains` app).
Command add_grains_index_command(CLI::App& grains);

// `grainlab grains import|fit-sh|spectrum` (registered by add_grains_command on
// its `grains` app): grains described by spherical harmonics.
Command add_grains_sh_commands(CLI::App& grains);

// The options of a command that meshes SH files: --faces, --unit, --max-degree.
void add_sh_file_options(CLI::App& cmd, int& faces, ShOptions& sh);

// `grainlab grains generate --spectrum FILE`: `count` random SH grains drawn
// from a spectrum file (io/sh_spectrum_file.h) written as binary STL files
// to `out`, with their shape beside the measured set's. `method`: a
// parse_sh_method name, or "" for shape-model when the file has a model and
// random-phase otherwise.
int run_generate_from_spectrum(const std::string& spectrum, const std::string& method, int count, std::uint64_t seed, const std::string& out,
                               int faces);

// `grainlab run`: a direct shear test from a config file.
Command add_run_command(CLI::App& app);

// `grainlab report`: the HTML report of one run folder, or a comparison of several.
Command add_report_command(CLI::App& app);

// `grainlab sweep SWEEP.toml`: a parameter sweep on Dask (python/grainlab/sweep.py).
Command add_sweep_command(CLI::App& app);

// `grainlab ct segment|synth`: X-ray CT volumes to grain meshes, and synthetic scans.
Command add_ct_command(CLI::App& app);

}  // namespace grainlab::apps
