#pragma once
/// Test helpers that run the built `plisse` executable and read its run directory.
#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

namespace plisse::test {

/// A fresh directory under the build tree for one test's output.
inline std::filesystem::path scratch_directory(const std::string& name) {
  const std::filesystem::path dir = std::filesystem::path(PLISSE_BINARY_DIR) / "test-runs" / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir.parent_path());
  return dir;
}

/// Runs `plisse ARGS` with stdout and stderr captured in `log`; returns the exit status.
inline int run_plisse(const std::string& args, const std::filesystem::path& log) {
  const std::string command =
      std::string(PLISSE_BINARY_DIR) + "/bin/plisse " + args + " > '" + log.string() + "' 2>&1";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/// Exit status and everything `plisse ARGS` printed (stdout and stderr).
struct PlisseResult {
  int status = -1;
  std::string output;
};

inline PlisseResult run_plisse_captured(const std::string& args) {
  const std::string command = std::string(PLISSE_BINARY_DIR) + "/bin/plisse " + args + " 2>&1";
  PlisseResult r;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return r;
  char buffer[4096];
  while (const std::size_t n = fread(buffer, 1, sizeof buffer, pipe)) r.output.append(buffer, n);
  const int status = pclose(pipe);
  r.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

inline std::string example(const std::string& name) {
  return std::string(PLISSE_SOURCE_DIR) + "/examples/" + name;
}

}  // namespace plisse::test
