#include "io/run_directory.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <system_error>

#include "core/error.hpp"

namespace plisse {

RunDirectory::RunDirectory(const std::filesystem::path& directory) {
  const InputPlace place{directory.string(), 0, 0, "-o"};
  if (directory.empty()) throw InputError(place, "the output directory name is empty");
  directory_ = directory.lexically_normal();
  if (!directory_.has_filename() && directory_.has_relative_path())
    directory_ = directory_.parent_path();  // "out/" -> "out"

  std::error_code error;
  std::filesystem::create_directories(directory_, error);
  if (error) throw InputError(place, "cannot create the output directory: " + error.message());
  if (!std::filesystem::is_directory(directory_, error))
    throw InputError(place, "the output path exists and is not a directory");

  // Permission bits alone do not tell (root, ACLs, read-only mounts): try to create a file.
  const std::filesystem::path probe =
      directory_ / (".plisse-write-probe." + std::to_string(static_cast<long>(::getpid())));
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
  if (fd < 0) {
    const int error_number = errno;
    throw InputError(place, "output directory is not writable: " +
                                std::generic_category().message(error_number));
  }
  ::close(fd);
  ::unlink(probe.c_str());
}

std::string RunDirectory::step_file_name(int step) {
  FE_CHECK(step >= 0, "step number " << step << " is negative");
  char name[32];
  std::snprintf(name, sizeof name, "step_%04d.vtu", step);
  return name;
}

}  // namespace plisse
