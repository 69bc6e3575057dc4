/// `plisse plot DIR [-o OUT]`: PNG figures of a run directory (docs/output.md, "Figures"), drawn
/// by scripts/plot.py with Debian's python3-matplotlib, so that a run on a cluster can be looked
/// at later without ParaView.
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "app/commands.hpp"
#include "core/error.hpp"

extern char** environ;

namespace plisse::app {
namespace {

namespace fs = std::filesystem;

struct PlotOptions {
  std::string run_directory;
  std::string output;  ///< default: DIR/plots
};

/// This executable's path, for the script to ask it for the output reference.
std::string own_executable() {
  std::array<char, 4096> path{};
  const ssize_t n = readlink("/proc/self/exe", path.data(), path.size() - 1);
  FE_CHECK(n > 0, "plisse plot: cannot find the plisse executable (/proc/self/exe)");
  return std::string(path.data(), static_cast<std::size_t>(n));
}

void plot(const PlotOptions& o) {
  const fs::path dir = o.run_directory;
  const InputPlace place{dir.string(), 0, 0, "DIR"};
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw InputError(place, "is not a run directory");
  if (!fs::is_regular_file(dir / "history.csv", ec))
    throw InputError(place, "holds no history.csv: not a plisse run directory, or no step done");
  const fs::path script = fs::path(PLISSE_SCRIPTS_DIR) / "plot.py";
  const std::string python = "/usr/bin/python3";
  if (access(python.c_str(), X_OK) != 0 || !fs::is_regular_file(script, ec))
    throw Error("plisse plot needs " + python + " with python3-matplotlib and python3-meshio " +
                "(Debian packages) and " + script.string());
  const std::string out = o.output.empty() ? (dir / "plots").string() : o.output;
  std::vector<std::string> args = {python, script.string(), dir.string(), out, own_executable()};
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t child = 0;
  const int spawned = posix_spawn(&child, python.c_str(), nullptr, nullptr, argv.data(), environ);
  FE_CHECK(spawned == 0, "plisse plot: cannot start " << python << " (error " << spawned << ")");
  int status = 0;
  while (waitpid(child, &status, 0) < 0)
    FE_CHECK(errno == EINTR, "plisse plot: waiting for the figures failed");
  if (WIFEXITED(status) && WEXITSTATUS(status) == 2)
    throw InputError(place, "is not a run directory plot.py can read (see above)");
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw Error("plisse plot: drawing the figures failed (see the messages above)");
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
