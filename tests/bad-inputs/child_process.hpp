#pragma once
/// Runs a program as a child process with a time limit (POSIX fork/exec), output to a file.
///
/// Unlike std::system, the caller learns whether the child exited, was killed by a signal (a
/// crash) or overran its time limit (a hang; the child is then killed with SIGKILL), and several
/// children can run at once.
#include <sys/types.h>

#include <filesystem>
#include <string>
#include <vector>

namespace plisse::test {

struct ChildResult {
  bool exited = false;  ///< normal exit; `status` is the exit status
  int status = -1;
  int signal = 0;          ///< the signal that ended the child, 0 when it exited
  bool timed_out = false;  ///< killed after the time limit
  double seconds = 0.0;    ///< wall time
  std::string output;      ///< stdout and stderr, interleaved
};

/// A started child: `program args...` in `working_directory`, stdout and stderr into `log`.
class ChildProcess {
 public:
  ChildProcess(const std::string& program, const std::vector<std::string>& args,
               const std::filesystem::path& working_directory, std::filesystem::path log);
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;
  /// Kills the child if it was never waited for.
  ~ChildProcess();

  /// Waits until the child ends or `limit_seconds` have passed since it started (then kills it).
  ChildResult wait(double limit_seconds);

 private:
  pid_t pid_ = -1;
  std::filesystem::path log_;
  double start_ = 0.0;
};

}  // namespace plisse::test
