/// `plisse plot DIR [-o OUT]`: PNG figures of a run directory (docs/output.md, "Figures"), drawn
/// by scripts/plot.py with Debian's python3-matplotlib, so that a run on a cluster can be looked
/// at later without ParaView.
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "app/commands.hpp"
#include "app/python_script.hpp"
#include "core/error.hpp"

namespace plisse::app {
namespace {

namespace fs = std::filesystem;

struct PlotOptions {
  std::string run_directory;
  std::string output;  ///< default: DIR/plots
};

void plot(const PlotOptions& o) {
  const fs::path dir = o.run_directory;
  const InputPlace place{dir.string(), 0, 0, "DIR"};
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw InputError(place, "is not a run directory");
  if (!fs::is_regular_file(dir / "history.csv", ec))
    throw InputError(place, "holds no history.csv: not a plisse run directory, or no step done");
  const std::string out = o.output.empty() ? (dir / "plots").string() : o.output;
  const int status =
      run_python_script("plisse plot", "plot.py", {dir.string(), out, own_executable()});
  if (status == 2)
    throw InputError(place, "plot.py refused the run directory or the figures' folder (see above)");
  if (status != 0) throw Error("plisse plot: drawing the figures failed (see the messages above)");
}

}  // namespace

void add_plot_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "plot",
      "Draw PNG figures of a run: forces, pressure against volume, Newton iterations, wrinkles "
      "and the wrinkle map (writes DIR/plots/; needs python3-matplotlib)");
  auto o = std::make_shared<PlotOptions>();
  cmd->add_option("dir", o->run_directory, "Run directory written by plisse run")->required();
  cmd->add_option("-o,--output", o->output, "Folder for the figures (default: DIR/plots)");
  cmd->callback([o] { plot(*o); });
}

}  // namespace plisse::app
