#include "core/input_file.hpp"

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <system_error>

#include "core/error.hpp"

namespace plisse {
namespace {

const char* kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

std::string with_unit(std::uintmax_t bytes) {
  if (bytes >= (std::uintmax_t{1} << 30) && bytes % (std::uintmax_t{1} << 30) == 0)
    return std::to_string(bytes >> 30) + " GiB";
  if (bytes >= (std::uintmax_t{1} << 20) && bytes % (std::uintmax_t{1} << 20) == 0)
    return std::to_string(bytes >> 20) + " MiB";
  return std::to_string(bytes) + " bytes";
}

}  // namespace

void check_input_file(const std::filesystem::path& path, std::uintmax_t max_bytes,
                      const std::string& what) {
  const InputPlace place{path.string(), 0, 0, ""};
  // O_NONBLOCK: opening a FIFO for reading would otherwise wait for a writer.
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) {
    const int error_number = errno;
    throw InputError(place, error_number == ENOENT
                                ? "the " + what + " does not exist"
                                : "cannot open the " + what + ": " +
                                      std::generic_category().message(error_number));
  }
  struct stat status {};
  const int stat_result = ::fstat(fd, &status);
  ::close(fd);
  if (stat_result != 0) throw InputError(place, "cannot read the " + what);
  if (!S_ISREG(status.st_mode))
    throw InputError(place, std::string("is ") + kind_of(status.st_mode) + ", not a " + what);
  const auto size = static_cast<std::uintmax_t>(status.st_size);
  if (size > max_bytes)
    throw InputError(place, "is " + std::to_string(size) + " bytes; a " + what + " is at most " +
                                with_unit(max_bytes) + " here");
}

std::uint64_t physical_memory_bytes() {
  const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGESIZE);
  std::uint64_t bytes = pages <= 0 || page <= 0
                            ? std::uint64_t{1} << 40
                            : static_cast<std::uint64_t>(pages) * static_cast<std::uint64_t>(page);
  // A process under an address-space limit (ulimit -v) can use no more than that.
  rlimit limit{};
  if (::getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY)
    bytes = std::min<std::uint64_t>(bytes, limit.rlim_cur);
  return bytes;
}

}  // namespace plisse
