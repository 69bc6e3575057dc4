#include "app/commands.hpp"

namespace plisse::app {

void add_materials_command(CLI::App& app) { app.add_subcommand("materials", "(not yet available)"); }

}  // namespace plisse::app
