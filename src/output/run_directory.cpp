#include "output/run_directory.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <functional>
#include <set>
#include <string_view>
#include <system_error>
#include <utility>

#include "core/error.hpp"
#include "output/append_file.hpp"
#include "output/atomic_file.hpp"

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
  PLISSE_CHECK(step >= 0, "step number " << step << " is negative");
  char name[32];
  std::snprintf(name, sizeof name, "step_%04d.vtu", step);
  return name;
}

namespace {

bool all_digits(std::string_view text) {
  return !text.empty() && std::all_of(text.begin(), text.end(),
                                      [](unsigned char c) { return std::isdigit(c) != 0; });
}

/// step_N.vtu, step_N.pvtu or step_N_pR.vtu.
bool is_step_file(std::string_view name) {
  if (name.substr(0, 5) != "step_") return false;
  name.remove_prefix(5);
  std::string_view extension;
  if (name.size() > 5 && name.substr(name.size() - 5) == ".pvtu")
    extension = ".pvtu";
  else if (name.size() > 4 && name.substr(name.size() - 4) == ".vtu")
    extension = ".vtu";
  else
    return false;
  name.remove_suffix(extension.size());
  const std::size_t piece = name.find("_p");
  if (piece == std::string_view::npos) return all_digits(name);
  return extension == ".vtu" && all_digits(name.substr(0, piece)) &&
         all_digits(name.substr(piece + 2));
}

std::string system_reason(int error_number) {
  return std::generic_category().message(error_number);
}

/// The names of a run's files other than its step files.
const std::set<std::string, std::less<>>& run_file_names() {
  static const std::set<std::string, std::less<>> names = {
      "history.csv",    "summary.json",         "solution.pvd", "log.txt",
      "checkpoint.bin", "wrinkle_spectrum.csv", "wrinkles.json"};
  return names;
}

bool is_run_file_name(std::string_view name) {
  return run_file_names().count(name) > 0 || is_step_file(name);
}

/// The name of the first symbolic link in `directory` at a name a run or `plisse wrinkles`
/// writes, or empty.
std::string linked_run_file(const std::filesystem::path& directory) {
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(directory, error)) {
    const std::string name = entry.path().filename().string();
    if (entry.is_symlink(error) && is_run_file_name(name)) return name;
  }
  return {};
}

}  // namespace

std::string output_path_problem(const std::filesystem::path& directory) {
  namespace fs = std::filesystem;
  std::error_code error;
  const fs::path normal = directory.lexically_normal();
  for (fs::path p = normal; !p.empty(); p = p.parent_path()) {
    if (fs::exists(p, error) && !fs::is_directory(p, error))
      return "cannot create the output directory: '" + p.string() +
             "' exists and is not a directory";
    if (p == p.parent_path()) break;
  }
  if (!fs::is_directory(normal, error)) return {};
  std::vector<std::string> taken;
  for (const auto& entry : fs::directory_iterator(normal, error)) {
    const std::string name = entry.path().filename().string();
    if (!entry.is_directory(error)) continue;
    if (is_run_file_name(name) || name == DirectoryLock::kFileName) taken.push_back(name);
  }
  if (taken.empty()) return {};
  std::sort(taken.begin(), taken.end());
  std::string names;
  for (const std::string& n : taken) names += (names.empty() ? "" : ", ") + n;
  return "holds a directory where the run writes a file (" + names +
         "): move it away or choose another -o";
}

std::vector<std::filesystem::path> run_files(const std::filesystem::path& directory) {
  std::vector<std::filesystem::path> files;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(directory, error)) {
    // A directory is the user's, whatever its name: never reported, never removed.
    if (entry.is_directory(error)) continue;
    if (is_run_file_name(entry.path().filename().string())) files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

int remove_run_files(const std::filesystem::path& directory) {
  int removed = remove_stale_temporaries(directory);
  for (const auto& file : run_files(directory)) {
    std::error_code error;
    std::filesystem::remove(file, error);
    if (error) throw Error("cannot remove '" + file.string() + "': " + error.message());
    ++removed;
  }
  return removed;
}

DirectoryLock::DirectoryLock(const std::filesystem::path& directory, const InputPlace& place)
    : file_(directory / kFileName) {
  // The holder removes the file when it lets go: a process that opened the old file just before
  // would lock a file no longer in the directory. Such a lock is dropped and taken again on the
  // file the path names now.
  for (int attempt = 0; attempt < 100; ++attempt) {
    fd_ = ::open(file_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
    if (fd_ < 0 && errno == ELOOP)
      throw InputError(place, "holds " + std::string(kFileName) + ", which " +
                                  std::string(kSymbolicLinkRefusal));
    if (fd_ < 0)
      throw InputError(
          place, "cannot create the lock file " + file_.string() + ": " + system_reason(errno));
    if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
      const int error_number = errno;
      std::string holder;
      char text[256] = {};
      const ssize_t n = ::pread(fd_, text, sizeof text - 1, 0);
      if (n > 0) holder.assign(text, static_cast<std::size_t>(n));
      while (!holder.empty() && (holder.back() == '\n' || holder.back() == '\r')) holder.pop_back();
      ::close(std::exchange(fd_, -1));
      if (error_number == EWOULDBLOCK)
        throw InputError(place, "is in use by another plisse process" +
                                    (holder.empty() ? std::string() : " (" + holder + ")") +
                                    "; wait for it to end, or choose another directory");
      throw InputError(place, "cannot lock " + file_.string() + ": " + system_reason(error_number));
    }
    struct stat opened {
    }, named{};
    if (::fstat(fd_, &opened) == 0 && ::stat(file_.c_str(), &named) == 0 &&
        opened.st_dev == named.st_dev && opened.st_ino == named.st_ino) {
      char host[256] = "unknown host";
      ::gethostname(host, sizeof host - 1);
      const std::string holder =
          "pid " + std::to_string(static_cast<long>(::getpid())) + " on " + host + "\n";
      // The holder's name is a courtesy to the message of a refused process: the lock holds
      // without it.
      const bool named_holder =
          ::ftruncate(fd_, 0) == 0 &&
          ::pwrite(fd_, holder.data(), holder.size(), 0) == static_cast<ssize_t>(holder.size());
      (void)named_holder;
      if (const std::string link = linked_run_file(directory); !link.empty()) {
        ::unlink(file_.c_str());
        ::close(std::exchange(fd_, -1));
        throw InputError(place, "holds " + link + ", which " + std::string(kSymbolicLinkRefusal));
      }
      return;
    }
    ::close(std::exchange(fd_, -1));
  }
  throw InputError(place, "cannot lock " + file_.string() + ": it keeps being replaced");
}

DirectoryLock::~DirectoryLock() {
  if (fd_ < 0) return;
  ::unlink(file_.c_str());
  ::close(fd_);
}

}  // namespace plisse
