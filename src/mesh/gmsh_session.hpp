#pragma once
/// Scoped, serialised access to the Gmsh SDK, which is one global, non-thread-safe state.
///
/// A `GmshSession` locks a process-wide mutex, initialises Gmsh on first use (once per process;
/// finalised at exit), silences its terminal output, and starts from an empty model. Gmsh
/// errors are collected through its logger rather than thrown: with the default
/// "General.AbortOnError" = 2 Gmsh throws from inside its readers and leaves itself locked,
/// so every later `open` silently reads nothing. Callers ask `check()` after each Gmsh call
/// that can fail, which turns logged errors into exceptions.
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace plisse {

class GmshSession {
 public:
  GmshSession();
  ~GmshSession();
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;

  /// Error messages Gmsh logged since the session began or since the last call (consumed).
  std::vector<std::string> take_errors();

  /// Throws InputError{file, "<what>: <gmsh messages>"} when Gmsh logged errors since the last
  /// check. `file` names the user's file (empty when there is none).
  void check_input(const std::string& file, const std::string& what);
  /// Same, but throws `Error` (for failures that are not the user's input, e.g. meshing).
  void check_internal(const std::string& what);

 private:
  std::unique_lock<std::mutex> lock_;
  std::size_t log_seen_ = 0;
};

}  // namespace plisse
