#pragma once
/// The subcommands of `plisse`. Each `add_*_command` registers its options on `app`; its callback
/// does the work and reports problems by throwing (InputError -> exit 2, SolverError -> exit 1).
#include <CLI/CLI.hpp>

namespace plisse::app {

void add_run_command(CLI::App& app);
void add_check_command(CLI::App& app);
void add_mesh_command(CLI::App& app);
void add_materials_command(CLI::App& app);
void add_wrinkles_command(CLI::App& app);

}  // namespace plisse::app
