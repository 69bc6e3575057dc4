#include "output/append_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <system_error>
#include <utility>

#include "core/error.hpp"

namespace plisse {
namespace {

[[noreturn]] void fail(const char* action, const std::filesystem::path& path, int error_number) {
  throw Error(std::string("cannot ") + action + " '" + path.string() +
              "': " + std::generic_category().message(error_number));
}

}  // namespace

AppendFile::AppendFile(std::filesystem::path path, bool replace) : path_(std::move(path)) {
  // O_NOFOLLOW: a symbolic link planted at the name is refused, never written through.
  const int flags =
      O_WRONLY | O_APPEND | O_CREAT | O_CLOEXEC | O_NOFOLLOW | (replace ? O_TRUNC : 0);
  fd_ = ::open(path_.c_str(), flags, 0666);
  if (fd_ < 0 && errno == ELOOP)
    throw InputError({path_.string(), 0, 0, ""}, std::string(kSymbolicLinkRefusal));
  if (fd_ < 0) fail("write", path_, errno);
}

AppendFile::~AppendFile() {
  if (fd_ >= 0) ::close(fd_);
}

AppendFile::AppendFile(AppendFile&& other) noexcept
    : path_(std::move(other.path_)), fd_(std::exchange(other.fd_, -1)) {}

AppendFile& AppendFile::operator=(AppendFile&& other) noexcept {
  if (this != &other) {
    if (fd_ >= 0) ::close(fd_);
    path_ = std::move(other.path_);
    fd_ = std::exchange(other.fd_, -1);
  }
  return *this;
}

void AppendFile::append(std::string_view text) {
  PLISSE_CHECK(fd_ >= 0, "cannot write '" << path_.string() << "': file is closed");
  if (text.empty()) return;
  struct stat before {};
  if (::fstat(fd_, &before) != 0) fail("write", path_, errno);
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd_, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int error_number = n < 0 ? errno : ENOSPC;
      // A partial line would be read as a damaged row: cut back to the last whole one.
      if (::ftruncate(fd_, before.st_size) != 0) {
        // Nothing better to do: the reader drops an unterminated last line.
      }
      fail("write", path_, error_number);
    }
    done += static_cast<std::size_t>(n);
  }
}

std::string_view complete_lines(std::string_view text) {
  const std::size_t last = text.rfind('\n');
  return last == std::string_view::npos ? std::string_view() : text.substr(0, last + 1);
}

}  // namespace plisse
