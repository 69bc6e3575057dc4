#include "mesh/isolated_process.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/time.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fstream>

#include "core/error.hpp"

/// Provided by the sanitizer runtimes (sanitizer/common_interface_defs.h); null without them.
extern "C" void __sanitizer_set_death_callback(void (*callback)()) __attribute__((weak));

namespace plisse {
namespace {

constexpr std::size_t kBufferBytes = std::size_t{1} << 16;
/// File descriptor of the pipe in the child (0-2 are /dev/null).
constexpr int kChildPipeFd = 3;

std::string errno_text() { return std::strerror(errno); }

/// Bytes currently mapped by this process (first field of /proc/self/statm, in pages), or 0.
std::uint64_t mapped_bytes() {
  std::ifstream statm("/proc/self/statm");
  std::uint64_t pages = 0;
  if (!(statm >> pages)) return 0;
  return pages * static_cast<std::uint64_t>(::sysconf(_SC_PAGESIZE));
}

void set_limit(int resource, rlim_t soft, rlim_t hard) {
  const rlimit limit{soft, hard};
  ::setrlimit(resource, &limit);  // best effort: the hard limit may already be lower
}

/// Everything in the child between fork and `work`: see isolated_process.hpp. Async-signal-safe
/// calls only until `work` runs (the parent may have other threads holding locks).
[[noreturn]] void run_child(int pipe_fd, const std::function<void(ChildOutput&)>& work,
                            const ChildLimits& limits, std::uint64_t parent_mapped) {
  // Default dispositions: a crash must end the child with its signal, not run a handler of the
  // parent (a sanitizer report, libFuzzer's crash handler saving the parent's input).
  for (int sig = 1; sig < NSIG; ++sig)
    if (sig != SIGKILL && sig != SIGSTOP) ::signal(sig, SIG_DFL);
  sigset_t none;
  sigemptyset(&none);
  ::sigprocmask(SIG_SETMASK, &none, nullptr);
  if (__sanitizer_set_death_callback) __sanitizer_set_death_callback(nullptr);
  ::prctl(PR_SET_DUMPABLE, 0, 0, 0, 0);
  set_limit(RLIMIT_CORE, 0, 0);

  // Descriptors: the pipe on 3, /dev/null on 0-2, nothing else (no file, socket or pipe of the
  // parent stays open in the child).
  const int high = ::fcntl(pipe_fd, F_DUPFD, 10);
  if (high < 0) ::_exit(kChildOutputFailed);
  const int null_fd = ::open("/dev/null", O_RDWR);
  for (int fd = 0; fd < 3; ++fd)
    if (null_fd >= 0) ::dup2(null_fd, fd);
  if (::dup2(high, kChildPipeFd) < 0) ::_exit(kChildOutputFailed);
  if (::close_range(kChildPipeFd + 1, ~0U, 0) != 0) {
    const long max_fd = std::min(::sysconf(_SC_OPEN_MAX), 1L << 16);
    for (long fd = kChildPipeFd + 1; fd < max_fd; ++fd) ::close(static_cast<int>(fd));
  }

  const rlim_t memory = static_cast<rlim_t>(parent_mapped + limits.memory_bytes);
  set_limit(RLIMIT_AS, memory, memory);
  const rlim_t cpu = std::max(1u, limits.cpu_seconds);
  set_limit(RLIMIT_CPU, cpu, cpu + 1);

  try {
    ChildOutput out(kChildPipeFd);
    work(out);
    out.flush();
  } catch (...) {
    ::_exit(kChildWorkThrew);
  }
  ::_exit(0);
}

/// Owns the child until it is reaped: kills and reaps it if the parent leaves early (exception).
class ChildGuard {
 public:
  explicit ChildGuard(pid_t pid) : pid_(pid) {}
  ~ChildGuard() {
    if (pid_ <= 0) return;
    ::kill(pid_, SIGKILL);
    int status = 0;
    while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
    }
  }
  ChildGuard(const ChildGuard&) = delete;
  ChildGuard& operator=(const ChildGuard&) = delete;
  /// Waits for the child; fills status and usage. Returns false if it could not be waited for.
  bool reap(int& status, rusage& usage) {
    pid_t got = 0;
    do {
      got = ::wait4(pid_, &status, 0, &usage);
    } while (got < 0 && errno == EINTR);
    pid_ = 0;
    return got > 0;
  }
  pid_t pid() const { return pid_; }

 private:
  pid_t pid_;
};

class FdGuard {
 public:
  explicit FdGuard(int fd) : fd_(fd) {}
  ~FdGuard() { close(); }
  FdGuard(const FdGuard&) = delete;
  FdGuard& operator=(const FdGuard&) = delete;
  void close() {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
  }
  int fd() const { return fd_; }

 private:
  int fd_;
};

double seconds(const timeval& t) {
  return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec);
}

}  // namespace

ChildOutput::ChildOutput(int fd) : fd_(fd) { buffer_.reserve(kBufferBytes); }

void ChildOutput::write(const void* data, std::size_t n_bytes) {
  const char* bytes = static_cast<const char*>(data);
  while (n_bytes > 0) {
    const std::size_t n = std::min(n_bytes, kBufferBytes - buffer_.size());
    buffer_.insert(buffer_.end(), bytes, bytes + n);
    bytes += n;
    n_bytes -= n;
    if (buffer_.size() == kBufferBytes) flush();
  }
}

void ChildOutput::flush() {
  std::size_t done = 0;
  while (done < buffer_.size()) {
    const ssize_t n = ::write(fd_, buffer_.data() + done, buffer_.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) ::_exit(kChildOutputFailed);  // the parent is gone or stopped reading
    done += static_cast<std::size_t>(n);
  }
  buffer_.clear();
}

bool ChildResult::cpu_limit_hit(const ChildLimits& limits) const {
  if (end != End::killed_by_signal) return false;
  return signal == SIGXCPU ||
         (signal == SIGKILL && cpu_seconds >= static_cast<double>(limits.cpu_seconds));
}

ChildResult run_isolated(const std::function<void(ChildOutput&)>& work, const ChildLimits& limits) {
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0)
    throw Error("cannot create a pipe for the isolated reader process: " + errno_text());
  FdGuard read_end(fds[0]), write_end(fds[1]);
  const std::uint64_t parent_mapped = mapped_bytes();
  std::fflush(nullptr);  // nothing buffered in stdio may be written twice
  const pid_t pid = ::fork();
  if (pid < 0) throw Error("cannot start the isolated reader process (fork): " + errno_text());
  if (pid == 0) run_child(write_end.fd(), work, limits, parent_mapped);
  ChildGuard child(pid);
  write_end.close();  // EOF on the read end once the child is gone

  ChildResult result;
  const auto deadline = std::chrono::steady_clock::now() +
                        std::chrono::duration<double>(std::max(0.0, limits.wall_seconds));
  std::vector<char> chunk(kBufferBytes);
  bool timed_out = false;
  while (true) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) {
      timed_out = true;
      break;
    }
    pollfd p{read_end.fd(), POLLIN, 0};
    const int ready = ::poll(&p, 1, static_cast<int>(std::min<long long>(left.count(), 60000)));
    if (ready < 0 && errno == EINTR) continue;
    if (ready < 0) throw Error("waiting for the isolated reader process (poll): " + errno_text());
    if (ready == 0) continue;
    const ssize_t n = ::read(read_end.fd(), chunk.data(), chunk.size());
    if (n < 0 && (errno == EINTR || errno == EAGAIN)) continue;
    if (n < 0) throw Error("reading from the isolated reader process: " + errno_text());
    if (n == 0) break;  // EOF: the child closed its end (normally by exiting)
    result.output.insert(result.output.end(), chunk.data(), chunk.data() + n);
  }
  if (timed_out) ::kill(child.pid(), SIGKILL);
  read_end.close();  // a child still writing gets EPIPE/SIGPIPE instead of blocking

  int status = 0;
  rusage usage{};
  if (!child.reap(status, usage))
    throw Error("cannot wait for the isolated reader process: " + errno_text());
  result.cpu_seconds = seconds(usage.ru_utime) + seconds(usage.ru_stime);
  result.max_rss_kib = usage.ru_maxrss;
  if (timed_out) {
    result.end = ChildResult::End::wall_time_exceeded;
  } else if (WIFSIGNALED(status)) {
    result.end = ChildResult::End::killed_by_signal;
    result.signal = WTERMSIG(status);
  } else {
    result.end = ChildResult::End::exited;
    result.exit_status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
  return result;
}

std::string describe_signal(int signal) {
  switch (signal) {
    case SIGSEGV:
      return "SIGSEGV (invalid memory access)";
    case SIGBUS:
      return "SIGBUS (invalid memory access)";
    case SIGABRT:
      return "SIGABRT (the library stopped itself)";
    case SIGFPE:
      return "SIGFPE (arithmetic error)";
    case SIGILL:
      return "SIGILL (illegal instruction)";
    case SIGXCPU:
      return "SIGXCPU (CPU-time limit)";
    case SIGKILL:
      return "SIGKILL";
    case SIGPIPE:
      return "SIGPIPE";
    default:
      return "signal " + std::to_string(signal);
  }
}

}  // namespace plisse
