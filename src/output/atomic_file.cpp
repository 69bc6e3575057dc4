#include "output/atomic_file.hpp"

#include <fcntl.h>
#include <signal.h>  // NOLINT(modernize-deprecated-headers): ::kill is POSIX's, not <csignal>'s
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cerrno>
#include <system_error>
#include <utility>

#include "core/error.hpp"

namespace plisse {
namespace {

std::string reason(int error_number) { return std::generic_category().message(error_number); }

[[noreturn]] void fail(const char* action, const std::filesystem::path& path, int error_number) {
  throw Error(std::string("cannot ") + action + " '" + path.string() +
              "': " + reason(error_number));
}

/// ".<name>.tmp.<pid>.<n>" beside the target: same directory, hence same file system, which
/// rename(2) needs to be atomic. pid and a process-wide counter keep concurrent writers apart.
/// `extension` (".msh") is appended for writers that choose the format from the name.
std::filesystem::path temporary_name(const std::filesystem::path& target,
                                     const std::string& extension = {}) {
  static std::atomic<unsigned long> counter{0};
  // Appended piecewise: GCC 12 gives a false -Wrestrict on `"." + std::string` (GCC bug 105329).
  std::string name(1, '.');
  name += target.filename().string();
  name += ".tmp.";
  name += std::to_string(static_cast<long>(::getpid()));
  name += '.';
  name += std::to_string(counter.fetch_add(1));
  name += extension;
  return target.parent_path() / name;
}

/// Writes all bytes, retrying on partial writes and EINTR. Returns 0 or the errno.
int write_all(int fd, const char* data, std::size_t n_bytes) {
  while (n_bytes > 0) {
    const ssize_t written = ::write(fd, data, n_bytes);
    if (written < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    data += written;
    n_bytes -= static_cast<std::size_t>(written);
  }
  return 0;
}

}  // namespace

AtomicFile::AtomicFile(std::filesystem::path target) : target_(std::move(target)) {
  PLISSE_CHECK(!target_.empty() && target_.has_filename(),
               "cannot write '" << target_.string() << "': not a file name");
  temporary_ = temporary_name(target_);
  fd_ = ::open(temporary_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC | O_NOFOLLOW, 0666);
  if (fd_ < 0) {
    const int error_number = errno;
    temporary_.clear();
    fail("write", target_, error_number);
  }
  buffer_.reserve(kBufferBytes);
}

AtomicFile::~AtomicFile() { discard(); }

AtomicFile::AtomicFile(AtomicFile&& other) noexcept
    : target_(std::move(other.target_)),
      temporary_(std::exchange(other.temporary_, {})),
      fd_(std::exchange(other.fd_, -1)),
      buffer_(std::move(other.buffer_)) {}

AtomicFile& AtomicFile::operator=(AtomicFile&& other) noexcept {
  if (this != &other) {
    discard();
    target_ = std::move(other.target_);
    temporary_ = std::exchange(other.temporary_, {});
    fd_ = std::exchange(other.fd_, -1);
    buffer_ = std::move(other.buffer_);
  }
  return *this;
}

void AtomicFile::write(const void* data, std::size_t n_bytes) {
  PLISSE_CHECK(fd_ >= 0, "cannot write '" << target_.string() << "': file is already closed");
  const char* bytes = static_cast<const char*>(data);
  if (buffer_.size() + n_bytes <= kBufferBytes) {
    buffer_.append(bytes, n_bytes);
    return;
  }
  flush_buffer();
  if (n_bytes < kBufferBytes) {
    buffer_.append(bytes, n_bytes);
  } else if (const int error_number = write_all(fd_, bytes, n_bytes); error_number != 0) {
    fail("write", target_, error_number);
  }
}

void AtomicFile::flush_buffer() {
  if (const int error_number = write_all(fd_, buffer_.data(), buffer_.size()); error_number != 0)
    fail("write", target_, error_number);
  buffer_.clear();
}

void AtomicFile::commit() {
  PLISSE_CHECK(fd_ >= 0, "cannot write '" << target_.string() << "': file is already closed");
  flush_buffer();
  // close() reports deferred write errors (e.g. NFS, disk full); check it before renaming.
  const int fd = std::exchange(fd_, -1);
  if (::close(fd) != 0) {
    const int error_number = errno;
    ::unlink(temporary_.c_str());
    temporary_.clear();
    fail("write", target_, error_number);
  }
  if (::rename(temporary_.c_str(), target_.c_str()) != 0) {
    const int error_number = errno;
    ::unlink(temporary_.c_str());
    temporary_.clear();
    fail("replace", target_, error_number);
  }
  temporary_.clear();
}

void AtomicFile::discard() noexcept {
  if (fd_ >= 0) ::close(std::exchange(fd_, -1));
  if (!temporary_.empty()) ::unlink(temporary_.c_str());
  temporary_.clear();
}

int remove_stale_temporaries(const std::filesystem::path& directory, std::string_view target_name) {
  const auto digits = [](std::string_view text) {
    return !text.empty() && text.size() < 12 &&
           std::all_of(text.begin(), text.end(), [](unsigned char c) { return std::isdigit(c); });
  };
  int removed = 0;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(directory, error)) {
    const std::string name = entry.path().filename().string();
    // ".<target>.tmp.<pid>.<n>" or ".<target>.tmp.<pid>.<n>.<extension>" (AtomicPath): the first
    // ".tmp." followed by two runs of digits.
    std::size_t tmp = name.find(".tmp.", 1);
    while (tmp != std::string::npos) {
      const std::string_view rest = std::string_view(name).substr(tmp + 5);
      const std::size_t dot = rest.find('.');
      const std::size_t end = dot == std::string_view::npos ? rest.size() : rest.find('.', dot + 1);
      if (dot != std::string_view::npos && digits(rest.substr(0, dot)) &&
          digits(rest.substr(dot + 1, end - dot - 1)))
        break;
      tmp = name.find(".tmp.", tmp + 1);
    }
    if (name.empty() || name[0] != '.' || tmp == std::string::npos) continue;
    if (!target_name.empty() && std::string_view(name).substr(1, tmp - 1) != target_name) continue;
    const std::string_view rest = std::string_view(name).substr(tmp + 5);
    const std::string pid(rest.substr(0, rest.find('.')));
    // kill(pid, 0) fails with ESRCH only when no such process exists.
    if (::kill(static_cast<pid_t>(std::stol(pid)), 0) == 0 || errno != ESRCH) continue;
    std::error_code remove_error;
    if (std::filesystem::remove(entry.path(), remove_error)) ++removed;
  }
  return removed;
}

std::string read_file(const std::filesystem::path& path, std::uintmax_t max_bytes) {
  // O_NONBLOCK: opening a FIFO would otherwise wait for a writer; it is refused below.
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) throw InputError({path.string(), 0, 0, ""}, "cannot read: " + reason(errno));
  struct stat status {};
  if (::fstat(fd, &status) != 0 || !S_ISREG(status.st_mode)) {
    ::close(fd);
    throw InputError({path.string(), 0, 0, ""},
                     S_ISDIR(status.st_mode)
                         ? "cannot read: is a directory"
                         : "cannot read: not a regular file (a FIFO, device or socket)");
  }
  if (static_cast<std::uintmax_t>(status.st_size) > max_bytes) {
    ::close(fd);
    throw InputError({path.string(), 0, 0, ""},
                     "cannot read: the file is " + std::to_string(status.st_size) +
                         " bytes, more than the " + std::to_string(max_bytes) +
                         " its reader accepts");
  }
  ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
  std::string content;
  content.reserve(static_cast<std::size_t>(status.st_size));
  char chunk[1 << 16];
  while (true) {
    const ssize_t n = ::read(fd, chunk, sizeof chunk);
    if (n == 0) break;
    if (n < 0) {
      if (errno == EINTR) continue;
      const int error_number = errno;
      ::close(fd);
      throw InputError({path.string(), 0, 0, ""}, "cannot read: " + reason(error_number));
    }
    content.append(chunk, static_cast<std::size_t>(n));
    if (content.size() > max_bytes) {  // grown since it was checked
      ::close(fd);
      throw InputError({path.string(), 0, 0, ""}, "cannot read: the file grew while it was read");
    }
  }
  ::close(fd);
  return content;
}

AtomicPath::AtomicPath(std::filesystem::path target) : target_(std::move(target)) {
  PLISSE_CHECK(!target_.empty() && target_.has_filename(),
               "cannot write '" << target_.string() << "': not a file name");
  temporary_ = temporary_name(target_, target_.extension().string());
}

AtomicPath::~AtomicPath() {
  if (!temporary_.empty()) ::unlink(temporary_.c_str());
}

void AtomicPath::commit() {
  PLISSE_CHECK(!temporary_.empty(), "cannot write '" << target_.string() << "': already committed");
  if (::rename(temporary_.c_str(), target_.c_str()) != 0) fail("replace", target_, errno);
  temporary_.clear();
}

void write_file_atomically(const std::filesystem::path& target, std::string_view content) {
  AtomicFile file(target);
  file.write(content);
  file.commit();
}

}  // namespace plisse
