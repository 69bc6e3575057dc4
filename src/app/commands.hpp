#pragma once
/// The subcommands of `plisse`. Each `add_*_command` registers its options on `app`; its callback
/// does the work and reports problems by throwing (InputError -> exit 2, SolverError -> exit 1).
#include <CLI/CLI.hpp>

namespace plisse::app {

void add_run_command(CLI::App& app);
void add_check_command(CLI::App& app);
void add_mesh_command(CLI::App& app);
void add_materials_command(CLI::App& app);
void add_case_keys_command(CLI::App& app);
void add_outputs_command(CLI::App& app);
void add_plot_command(CLI::App& app);
void add_wrinkles_command(CLI::App& app);
void add_fit_command(CLI::App& app);

/// The process's own command line (set by main), for commands that start it again (run -n N).
struct CommandLine {
  int argc = 0;
  char** argv = nullptr;
};
CommandLine& command_line();

}  // namespace plisse::app
