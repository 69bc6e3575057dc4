#include <iostream>
#include <string>

#include "app/commands.hpp"
#include "core/error.hpp"

namespace plisse::app {

void add_run_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("run", "Run a case: solve and write the run directory");
  auto case_file = std::make_shared<std::string>();
  cmd->add_option("case", *case_file, "Case file (YAML)")->required();
  cmd->callback([case_file] {
    throw SolverError("plisse run: the solver is not available yet in this build");
  });
}

}  // namespace plisse::app
