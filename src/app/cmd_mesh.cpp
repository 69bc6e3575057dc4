#include "app/commands.hpp"

namespace plisse::app {

void add_mesh_command(CLI::App& app) { app.add_subcommand("mesh", "(not yet available)"); }

}  // namespace plisse::app
