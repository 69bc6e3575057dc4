#pragma once
/// Files that grow by whole lines: history.csv, log.txt and wrinkle_spectrum.csv are appended to,
/// a row or a step at a time, instead of being rewritten whole (an 8 000-step run would otherwise
/// write gigabytes to keep a few megabytes).
///
/// Guarantee: each append() is one write(2) on an O_APPEND descriptor, and a failed or short write
/// is cut back (ftruncate) to the file's previous end, so the file always ends in a whole line
/// unless the process dies inside the write itself. Readers that continue such a file after a
/// SIGKILL drop an unterminated last line (complete_lines()).
#include <filesystem>
#include <string_view>

namespace plisse {

/// Why a symbolic link where plisse writes a file is refused (docs/architecture.md, "Interface
/// contract"): the message of the InputError that names it.
inline constexpr std::string_view kSymbolicLinkRefusal =
    "is a symbolic link; plisse writes no file through a link (its target could be any file the "
    "user may write): remove the link";

class AppendFile {
 public:
  /// Opens `path` for appending. `replace`: creates it empty, discarding any earlier content;
  /// otherwise creates it if missing and keeps what it holds. A symbolic link at `path` is not
  /// followed: InputError (file = path, kSymbolicLinkRefusal). Throws plisse::Error (path,
  /// strerror) if it cannot be opened otherwise.
  AppendFile(std::filesystem::path path, bool replace);
  ~AppendFile();
  AppendFile(AppendFile&& other) noexcept;
  AppendFile& operator=(AppendFile&& other) noexcept;
  AppendFile(const AppendFile&) = delete;
  AppendFile& operator=(const AppendFile&) = delete;

  /// Appends `text` in one write. On failure (disk full, I/O error) the file is cut back to its
  /// length before the call and plisse::Error (path, strerror) is thrown.
  void append(std::string_view text);
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
  int fd_ = -1;
};

/// `text` up to and including its last '\n': the whole lines of a file an appending writer may
/// have been killed in (the unterminated rest is what the interrupted write left).
std::string_view complete_lines(std::string_view text);

}  // namespace plisse
