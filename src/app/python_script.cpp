#include "app/python_script.hpp"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <filesystem>

#include "core/error.hpp"

extern char** environ;

namespace plisse::app {

std::string own_executable() {
  std::array<char, 4096> path{};
  const ssize_t n = readlink("/proc/self/exe", path.data(), path.size() - 1);
  PLISSE_CHECK(n > 0, "cannot find the plisse executable (/proc/self/exe)");
  return std::string(path.data(), static_cast<std::size_t>(n));
}

int run_python_script(const std::string& command, const std::string& script,
                      const std::vector<std::string>& args) {
  const std::filesystem::path path = std::filesystem::path(PLISSE_SCRIPTS_DIR) / script;
  const std::string python = "/usr/bin/python3";
  std::error_code ec;
  if (access(python.c_str(), X_OK) != 0 || !std::filesystem::is_regular_file(path, ec))
    throw Error(command + " needs " + python + " with python3-matplotlib and python3-meshio " +
                "(Debian packages) and " + path.string());
  std::vector<std::string> all = {python, path.string()};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t child = 0;
  const int spawned = posix_spawn(&child, python.c_str(), nullptr, nullptr, argv.data(), environ);
  PLISSE_CHECK(spawned == 0,
               command << ": cannot start " << python << " (error " << spawned << ")");
  int status = 0;
  while (waitpid(child, &status, 0) < 0)
    PLISSE_CHECK(errno == EINTR, command << ": waiting for " << script << " failed");
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace plisse::app
