#pragma once
/// The run's log: messages go to the terminal at once and are kept for log.txt.
///
/// Terminal: info lines on stdout as given; warnings ("warning: ...") and errors
/// ("error: ...") on stderr. log.txt: every line prefixed with the wall time elapsed since the
/// log was created, "[   12.3s] message". log.txt is rewritten atomically on flush() (the solver
/// calls it after each step and at exit; the destructor calls it too), so it is never truncated.
/// A multi-line message becomes several lines, each prefixed. Thread-safe. In a distributed run
/// only one rank (rank 0) should own a RunLog with a file: ranks do not coordinate here.
#include <chrono>
#include <filesystem>
#include <iosfwd>
#include <mutex>
#include <string>
#include <string_view>
#include <vector>

namespace plisse {

class RunLog {
 public:
  /// `log_file`: the log.txt to maintain, or empty for a terminal-only log (e.g. `plisse check`).
  /// `out`/`err`: where info resp. warnings and errors are echoed (borrowed, must outlive the
  /// log; nullptr = do not echo). The clock starts now.
  explicit RunLog(std::filesystem::path log_file, std::ostream* out, std::ostream* err);
  /// Same with out = std::cout, err = std::cerr.
  explicit RunLog(std::filesystem::path log_file);
  /// Flushes; a write failure here is reported on `err`, not thrown.
  ~RunLog();
  RunLog(const RunLog&) = delete;
  RunLog& operator=(const RunLog&) = delete;

  void info(std::string_view message);
  void warn(std::string_view message);   ///< logged as "warning: message"
  void error(std::string_view message);  ///< logged as "error: message"

  /// Rewrites log_file with all lines so far (atomically). Throws plisse::Error naming the path
  /// if it cannot be written. No-op for a terminal-only log.
  void flush();

  /// Puts `text` (the lines of an earlier log.txt, e.g. of the run being resumed) before the lines
  /// of this log; it is not echoed.
  void prepend(std::string_view text);
  /// Wall time since construction [s].
  double elapsed_seconds() const;
  /// The lines of log.txt so far, with their time prefix, without line breaks.
  std::vector<std::string> lines() const;
  const std::filesystem::path& log_file() const { return log_file_; }

 private:
  void add(std::string_view prefix, std::string_view message, std::ostream* echo);

  std::filesystem::path log_file_;
  std::ostream* out_;
  std::ostream* err_;
  std::chrono::steady_clock::time_point start_;
  mutable std::mutex mutex_;
  std::string text_;  ///< content of log.txt: prefixed lines, each ending in '\n'
};

}  // namespace plisse
