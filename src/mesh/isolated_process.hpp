#pragma once
/// Running work on untrusted input (a third-party file reader) in a forked child process, so that
/// a crash, an unbounded allocation or an endless loop in that code ends the child, not plisse.
///
/// `run_isolated(work, limits)` forks; the child runs `work`, which writes its result to a
/// `ChildOutput` (a pipe to the parent), and leaves with `_exit(0)`. The parent collects the bytes
/// and how the child ended. The child:
/// - gets resource limits: address space (RLIMIT_AS, counted on top of what was mapped at the
///   fork, so that sanitizer shadow memory does not count), CPU time (RLIMIT_CPU: SIGXCPU, then
///   SIGKILL one second later), no core dump (RLIMIT_CORE = 0, not dumpable);
/// - has stdin, stdout and stderr on /dev/null (third-party code prints), and no other file
///   descriptor of the parent;
/// - has default signal dispositions, no blocked signal, and no sanitizer death callback (under
///   libFuzzer that callback would save the parent's input as a finding of its own);
/// - never returns into the caller's stack and leaves by `_exit`: no atexit handler, static
///   destructor, MPI/PETSc finalisation or leak check of the parent runs in the child.
/// The parent enforces a wall-clock limit (SIGKILL), always reaps the child (no zombie, also when
/// it throws), retries on EINTR, and reads through a close-on-exec pipe.
///
/// Not thread-safe with respect to other forks of the same process only in the usual POSIX sense:
/// the child runs nothing but `work`, which must not wait for locks other threads may hold
/// (allocation through malloc is fine: glibc resets its locks in the child).
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace plisse {

/// Resource limits of the child.
struct ChildLimits {
  std::uint64_t memory_bytes = 0;  ///< address space the child may map beyond the parent's [B]
  unsigned cpu_seconds = 0;        ///< CPU time (user + system) [s], >= 1
  double wall_seconds = 0.0;       ///< real time after which the parent kills the child [s]
};

/// The child's end of the pipe: buffered writes. A failed write ends the child at once
/// (exit status `kChildOutputFailed`), since no one reads what it would send.
class ChildOutput {
 public:
  explicit ChildOutput(int fd);
  ChildOutput(const ChildOutput&) = delete;
  ChildOutput& operator=(const ChildOutput&) = delete;
  void write(const void* data, std::size_t n_bytes);
  void flush();

 private:
  int fd_;
  std::vector<char> buffer_;
};

/// Exit statuses of the child besides 0 (sent everything) and what a sanitizer uses.
inline constexpr int kChildWorkThrew = 125;
inline constexpr int kChildOutputFailed = 126;

/// How the child ended and what it sent.
struct ChildResult {
  enum class End {
    exited,             ///< `exit_status` holds its exit status
    killed_by_signal,   ///< `signal` holds the signal number
    wall_time_exceeded  ///< killed by the parent after ChildLimits::wall_seconds
  };
  End end = End::exited;
  int exit_status = 0;
  int signal = 0;
  double cpu_seconds = 0.0;      ///< CPU time the child used (user + system) [s]
  std::int64_t max_rss_kib = 0;  ///< its peak resident set [KiB] (getrusage's ru_maxrss)
  std::vector<char> output;      ///< everything it wrote to its ChildOutput

  /// True when the child ran into its CPU-time limit (SIGXCPU, or the SIGKILL that follows it).
  bool cpu_limit_hit(const ChildLimits& limits) const;
};

/// Runs `work` in a forked child with `limits` (see the file comment) and returns how it ended.
/// `work` must not throw (if it does, the child exits with kChildWorkThrew). Throws plisse::Error
/// when the child cannot be started (pipe, fork), which is not a property of the input.
ChildResult run_isolated(const std::function<void(ChildOutput&)>& work, const ChildLimits& limits);

/// "SIGSEGV (invalid memory access)" and so on for the signals a crashing reader dies of;
/// "signal N" for others.
std::string describe_signal(int signal);

}  // namespace plisse
