#pragma once
/// The run's log: messages go to the terminal at once and are kept for log.txt.
///
/// Terminal: info lines on stdout as given; warnings ("warning: ...") and errors
/// ("error: ...") on stderr. log.txt: every line prefixed with the wall time elapsed since the
/// log was created, "[   12.3s] message". flush() appends the lines since the last flush to
/// log.txt in one write (the solver calls it after each step and at exit; the destructor calls it
/// too), so the file holds whole lines and is not rewritten as it grows.
/// A multi-line message becomes several lines, each prefixed. Thread-safe. In a distributed run
/// only one rank (rank 0) should own a RunLog with a file: ranks do not coordinate here.
#include <chrono>
#include <filesystem>
#include <iosfwd>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "output/append_file.hpp"

namespace plisse {

/// What the first flush does with an existing log file.
enum class LogStart {
  replace,  ///< a new run: the file starts empty
  append,   ///< a resumed run: its lines follow those of the run it continues
};

class RunLog {
 public:
  /// `log_file`: the log.txt to maintain, or empty for a terminal-only log (e.g. `plisse check`).
  /// `out`/`err`: where info resp. warnings and errors are echoed (borrowed, must outlive the
  /// log; nullptr = do not echo). The clock starts now.
  explicit RunLog(std::filesystem::path log_file, std::ostream* out, std::ostream* err,
                  LogStart start = LogStart::replace);
  /// Same with out = std::cout, err = std::cerr.
  explicit RunLog(std::filesystem::path log_file, LogStart start = LogStart::replace);
  /// Flushes; a write failure here is reported on `err`, not thrown.
  ~RunLog();
  RunLog(const RunLog&) = delete;
  RunLog& operator=(const RunLog&) = delete;

  void info(std::string_view message);
  void warn(std::string_view message);   ///< logged as "warning: message"
  void error(std::string_view message);  ///< logged as "error: message"

  /// Appends the lines added since the last flush to log_file. Throws plisse::Error naming the
  /// path if it cannot be written (the lines are kept for the next flush). No-op for a
  /// terminal-only log.
  void flush();

  /// Wall time since construction [s].
  double elapsed_seconds() const;
  /// The lines this log added so far, with their time prefix, without line breaks.
  std::vector<std::string> lines() const;
  const std::filesystem::path& log_file() const { return log_file_; }

 private:
  void add(std::string_view prefix, std::string_view message, std::ostream* echo);

  std::filesystem::path log_file_;
  std::ostream* out_;
  std::ostream* err_;
  std::chrono::steady_clock::time_point start_;
  mutable std::mutex mutex_;
  LogStart start_mode_;
  std::optional<AppendFile> file_;  ///< opened by the first flush
  std::string text_;                ///< this log's lines: prefixed, each ending in '\n'
  std::size_t written_ = 0;         ///< bytes of text_ already in log_file
};

}  // namespace plisse
