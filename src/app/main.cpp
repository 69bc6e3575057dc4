/// plisse command line: `plisse run|check|mesh|materials|wrinkles ...` (see `plisse --help`).
///
/// Exit status (DESIGN.md, interface contract): 0 success; 1 solver failure (last converged state
/// written) or an internal error; 2 bad input (message names file, line, column, key and rule).
#include <CLI/CLI.hpp>
#include <exception>
#include <iostream>
#include <string>

#include "app/commands.hpp"
#include "core/error.hpp"

int main(int argc, char** argv) {
  CLI::App app{
      "plisse: wrinkling and buckling of thin incompressible hyperelastic membranes\n"
      "(3-D mixed P1+/P1 tetrahedra; units mm, MPa, s, tonne/mm^3)"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "plisse 0.1.0");
  plisse::app::add_run_command(app);
  plisse::app::add_check_command(app);
  plisse::app::add_mesh_command(app);
  plisse::app::add_materials_command(app);
  plisse::app::add_wrinkles_command(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return 2;
  } catch (const plisse::InputError& e) {
    std::cerr << "plisse: error: " << e.what() << '\n';
    return 2;
  } catch (const plisse::SolverError& e) {
    std::cerr << "plisse: solver failure: " << e.what() << '\n';
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "plisse: error: " << e.what() << '\n';
    return 1;
  } catch (const std::string& message) {  // Gmsh's API throws its messages as strings
    std::cerr << "plisse: error: " << message << '\n';
    return 1;
  } catch (...) {  // anything else would end in std::terminate and SIGABRT
    std::cerr << "plisse: error: an exception of unknown type\n";
    return 1;
  }
  return 0;
}
