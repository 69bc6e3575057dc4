#pragma once
/// Test helpers that run the built `plisse` executable and read its run directory.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "support/sanitizer.hpp"

namespace plisse::test {

/// A fresh directory under the build tree for one test's output, inside a folder named after the
/// running test: CTest runs tests in parallel processes, and two tests that chose the same `name`
/// would otherwise wipe and write each other's runs. A validation test's full-tier build (the
/// same source with PLISSE_VALIDATION_FULL=1, CTest suffix .full) gets a folder of its own, so
/// that the two tiers can run at once.
inline std::filesystem::path scratch_directory(const std::string& name) {
  std::filesystem::path dir = std::filesystem::path(PLISSE_BINARY_DIR) / "test-runs";
  if (const auto* test = ::testing::UnitTest::GetInstance()->current_test_info()) {
    dir /= std::string(test->test_suite_name()) + "." + test->name();
#if defined(PLISSE_VALIDATION_FULL) && PLISSE_VALIDATION_FULL
    dir += ".full";
#endif
  }
  dir /= name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir.parent_path());
  return dir;
}

/// `x` with 6 significant digits (printf's %.6g), as the tests write the values of `--set` and
/// the names of their runs.
inline std::string six_digits(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", x);
  return text;
}

/// Runs `plisse ARGS` with stdout and stderr captured in `log`; returns the exit status.
inline int run_plisse(const std::string& args, const std::filesystem::path& log) {
  const std::string command =
      std::string(PLISSE_BINARY_DIR) + "/bin/plisse " + args + " > '" + log.string() + "' 2>&1";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/// A shell prefix that limits the command after it to `seconds` of wall time and 4 GiB of
/// address space, except under AddressSanitizer, which reserves terabytes of address space for
/// its shadow memory (scripts/sanitize): then to the time only.
inline std::string limits(int seconds) {
  return (kAddressSanitizer ? "" : "ulimit -v 4194304; ") + std::string("timeout ") +
         std::to_string(seconds) + " ";
}

/// Exit status and everything `plisse ARGS` printed (stdout and stderr).
struct PlisseResult {
  int status = -1;
  std::string output;
};

/// `prefix` goes before the executable in the shell command: a launcher or limits, e.g.
/// "mpiexec -n 2 " or "ulimit -v 4194304; timeout 30 ".
inline PlisseResult run_plisse_captured(const std::string& args, const std::string& prefix = "") {
  const std::string command =
      prefix + std::string(PLISSE_BINARY_DIR) + "/bin/plisse " + args + " 2>&1";
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

/// Starts `plisse ARGS...` in the background, stdout and stderr in `log`; returns its pid (for
/// kill and waitpid: the fault tests).
inline pid_t start_plisse(const std::vector<std::string>& args, const std::filesystem::path& log) {
  const std::string exe = std::string(PLISSE_BINARY_DIR) + "/bin/plisse";
  const pid_t pid = fork();
  if (pid == 0) {
    if (!std::freopen(log.c_str(), "w", stdout) || !std::freopen(log.c_str(), "a", stderr))
      _exit(126);
    std::vector<std::string> words = {exe};
    words.insert(words.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (auto& w : words) argv.push_back(w.data());
    argv.push_back(nullptr);
    execv(exe.c_str(), argv.data());
    _exit(127);
  }
  return pid;
}

/// Data rows of dir/history.csv so far (0 while it does not exist).
inline std::size_t history_rows(const std::filesystem::path& dir) {
  std::ifstream in(dir / "history.csv");
  std::size_t lines = 0;
  for (std::string line; std::getline(in, line);) ++lines;
  return lines > 0 ? lines - 1 : 0;
}

/// Waits (at most `limit`) until dir/history.csv has `rows` rows; false if it never does.
inline bool wait_for_history_rows(const std::filesystem::path& dir, std::size_t rows,
                                  std::chrono::seconds limit = std::chrono::seconds(60)) {
  const auto deadline = std::chrono::steady_clock::now() + limit;
  while (history_rows(dir) < rows && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  return history_rows(dir) >= rows;
}

}  // namespace plisse::test
