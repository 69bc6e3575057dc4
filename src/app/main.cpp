/// plisse command line: `plisse run|check|mesh|materials|case-keys|wrinkles ...`
/// (see `plisse --help`).
///
/// Exit status (docs/architecture.md, "Interface contract"): 0 success; 1 solver failure (last
/// converged state written) or an internal error; 2 bad input (message names file, line, column,
/// key and rule).
#include <CLI/CLI.hpp>
#include <csignal>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <string>

#include "app/commands.hpp"
#include "core/error.hpp"

namespace plisse::app {
CommandLine& command_line() {
  static CommandLine line;
  return line;
}
}  // namespace plisse::app

namespace {
/// In a distributed run every rank fails alike: only the first one reports it.
bool reports_errors() {
  for (const char* name : {"OMPI_COMM_WORLD_RANK", "PMIX_RANK", "PMI_RANK"})
    if (const char* value = std::getenv(name)) return std::atoi(value) == 0;
  return true;
}
std::ostream& error_stream() {
  static std::ostream silent(nullptr);
  return reports_errors() ? std::cerr : silent;
}
}  // namespace

int main(int argc, char** argv) {
  plisse::app::command_line() = {argc, argv};
  // Past a file size limit (ulimit -f) a write fails with EFBIG, which the writers report naming
  // the file, instead of the signal SIGXFSZ ending the process with the file half written.
  std::signal(SIGXFSZ, SIG_IGN);
  CLI::App app{
      "plisse: wrinkling and buckling of thin incompressible hyperelastic membranes\n"
      "(3-D mixed tetrahedra, Taylor-Hood P2/P1 or MINI P1+/P1, and rotation-free shell\n"
      "triangles; in the case's own consistent units: mm, N, MPa, s, tonne/mm^3 in the docs)"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "plisse 0.1.0");
  plisse::app::add_run_command(app);
  plisse::app::add_check_command(app);
  plisse::app::add_mesh_command(app);
  plisse::app::add_materials_command(app);
  plisse::app::add_case_keys_command(app);
  plisse::app::add_outputs_command(app);
  plisse::app::add_plot_command(app);
  plisse::app::add_wrinkles_command(app);
  plisse::app::add_fit_command(app);
  // A first word that names no command is refused before anything else: CLI11 would answer
  // `plisse NOSUCH --help` with the general help and exit status 0.
  if (argc > 1 && argv[1][0] != '-') {
    const std::string word = argv[1];
    std::string names;
    bool known = false;
    for (const CLI::App* command : app.get_subcommands({})) {
      known = known || command->get_name() == word;
      names += (names.empty() ? "" : ", ") + command->get_name();
    }
    if (!known) {
      error_stream() << "plisse: error: unknown command " << plisse::quoted_excerpt(word)
                     << " (commands: " << names << "; plisse --help lists them)\n";
      return 2;
    }
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    return app.exit(e);
  } catch (const CLI::ExtrasError& e) {
    // An option that another command takes (`plisse check -n 4`): say whose it is.
    for (const CLI::App* used : app.get_subcommands())
      for (const std::string& extra : used->remaining())
        for (const CLI::App* other : app.get_subcommands({}))
          if (other != used && extra.size() > 1 && extra[0] == '-' &&
              other->get_option_no_throw(extra) != nullptr) {
            error_stream() << "plisse: error: " << used->get_name() << " takes no " << extra
                           << ": it is an option of plisse " << other->get_name() << " ("
                           << e.what() << ")\n";
            return 2;
          }
    app.exit(e);
    return 2;
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return 2;
  } catch (const plisse::InputError& e) {
    error_stream() << "plisse: error: " << e.what() << '\n';
    return 2;
  } catch (const plisse::SolverError& e) {
    error_stream() << "plisse: solver failure: " << e.what() << '\n';
    return 1;
  } catch (const std::exception& e) {
    error_stream() << "plisse: error: " << e.what() << '\n';
    return 1;
  } catch (const std::string& message) {  // Gmsh's API throws its messages as strings
    error_stream() << "plisse: error: " << message << '\n';
    return 1;
  } catch (...) {  // anything else would end in std::terminate and SIGABRT
    error_stream() << "plisse: error: an exception of unknown type\n";
    return 1;
  }
  return 0;
}
