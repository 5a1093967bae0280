#pragma once
// `acdplan env`: load any world (or a scenario's world) and report what was loaded.

#include <CLI/CLI.hpp>
#include <string>

namespace acdplan::tools {

/// What `acdplan env` was asked.
struct EnvArguments {
  std::string input;       ///< A world file of any kind, or a scenario YAML.
  double tau_diag = -1.0;  ///< ACD tau / bounds diagonal; < 0: the scenario's, else 0.02.
  double tau_rel = -1.0;   ///< The older spelling of --tau-diag (read with a warning).
  std::string measure;     ///< "" : the scenario's, else sp.
  bool repair = false;     ///< Make invalid obstacle polygons valid (acd::RepairPolygon).
  std::string unknown;     ///< Occupancy maps' unknown cells: "blocked" or "free"; "": blocked.
  int problem = -1;        ///< Of a Moving AI .scen file; < 0: its first.
  std::string svg_path;    ///< 2D: the world and its free-space decomposition.
  std::string json_path;   ///< The report as JSON.
};

/// Adds the `env` subcommand to `app`, filling `args`; returns it.
CLI::App* AddEnvCommand(CLI::App* app, EnvArguments* args);

/// Runs `acdplan env`; returns the exit status.
/// @throws acdplan::InputError for a world that cannot be loaded or an unwritable output.
int RunEnv(const EnvArguments& args);

}  // namespace acdplan::tools
