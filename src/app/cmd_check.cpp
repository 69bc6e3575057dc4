#include "app/commands.hpp"

namespace plisse::app {

void add_check_command(CLI::App& app) { app.add_subcommand("check", "(not yet available)"); }

}  // namespace plisse::app
