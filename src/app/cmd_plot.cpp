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
  std::string output;          ///< default: DIR/plots
  std::string x;               ///< --x: the abscissa of columns.png (default time)
  std::vector<std::string> y;  ///< --y: the columns of columns.png; none: the default figures
  std::string line;            ///< --line AX,AY,AZ:BX,BY,BZ: line.csv and line.png instead
  int points = 200;            ///< --points: samples along the line
  int step = -1;               ///< --step: the written step sampled; -1 the last
};

void plot(const PlotOptions& o) {
  const fs::path dir = o.run_directory;
  const InputPlace place{dir.string(), 0, 0, "DIR"};
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw InputError(place, "is not a run directory");
  if (!fs::is_regular_file(dir / "history.csv", ec))
    throw InputError(place, "holds no history.csv: not a plisse run directory, or no step done");
  if (!o.x.empty() && o.y.empty())
    throw InputError(InputPlace{"command line", 0, 0, "--x"},
                     "needs at least one --y column to draw against it");
  const std::string out = o.output.empty() ? (dir / "plots").string() : o.output;
  std::vector<std::string> args{dir.string(), out, own_executable()};
  if (!o.x.empty()) args.insert(args.end(), {"--x", o.x});
  for (const std::string& column : o.y) args.insert(args.end(), {"--y", column});
  if (!o.line.empty())
    args.insert(args.end(), {"--line", o.line, "--points", std::to_string(o.points)});
  if (o.step >= 0) args.insert(args.end(), {"--step", std::to_string(o.step)});
  const int status = run_python_script("plisse plot", "plot.py", args);
  if (status == 2)
    throw InputError(place,
                     "plot.py refused the run directory, the figures' folder or a column (see "
                     "above)");
  if (status != 0) throw Error("plisse plot: drawing the figures failed (see the messages above)");
}

}  // namespace

void add_plot_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "plot",
      "Draw PNG figures of a run: forces, moments, pressure against volume, Newton iterations, "
      "wrinkles and the wrinkle map, or history columns of your choice with --y (and --x), or "
      "the fields along a line with --line (writes DIR/plots/; needs python3-matplotlib)");
  auto o = std::make_shared<PlotOptions>();
  cmd->add_option("dir", o->run_directory, "Run directory written by plisse run")->required();
  cmd->add_option("-o,--output", o->output, "Folder for the figures (default: DIR/plots)");
  cmd->add_option("--y", o->y,
                  "A history.csv column to draw (repeat for several): draws only columns.png, "
                  "these columns against --x")
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  cmd->add_option("--x", o->x, "The history.csv column of columns.png's abscissa (default time)");
  cmd->add_option("--line", o->line,
                  "AX,AY,AZ:BX,BY,BZ: the fields of a written step along this segment of the "
                  "undeformed body, in line.csv and line.png (instead of the figures)");
  cmd->add_option("--points", o->points, "Points sampled along --line (default 200)")
      ->check(CLI::Range(2, 100000));
  cmd->add_option("--step", o->step, "The written step --line samples (default the last)")
      ->check(CLI::NonNegativeNumber);
  cmd->callback([o] { plot(*o); });
}

}  // namespace plisse::app
