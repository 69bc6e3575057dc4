#pragma once
/// Atomic replacement of a file: write everything to a temporary file in the target's directory,
/// then rename(2) it over the target. rename within one file system is atomic (POSIX), so a reader
/// (ParaView, a plotting script) or a run killed mid-write sees either the old file whole or the
/// new file whole, never a truncated one. Every file of a run directory is written this way.
///
/// Guarantee and limit: this protects against the process dying (kill, crash, exception). It does
/// not fsync, so after a power loss the newest version may be lost; the previous one survives.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace plisse {

/// Writes `content` to `target` atomically (see file comment). The temporary file
/// `.<name>.tmp.<pid>.<n>` lives beside the target and is removed on failure. Creates a new file
/// with mode 0666 & ~umask; an existing target is replaced whole (its old mode is not kept).
/// Throws plisse::Error naming the path and the system's reason (strerror) when anything fails;
/// the target is then untouched.
void write_file_atomically(const std::filesystem::path& target, std::string_view content);

/// Removes from `directory` the temporary files of write_file_atomically, AtomicFile and
/// AtomicPath that a writer killed mid-write left behind (SIGKILL, power loss): the names
/// `.<name>.tmp.<pid>.<n>` and `.<name>.tmp.<pid>.<n>.<extension>` whose process <pid> no longer
/// runs. Temporaries of live processes (another run writing into the same directory) are kept.
/// With `target_name`, only the temporaries of that file name. Returns how many were removed; a
/// file that cannot be removed is skipped.
int remove_stale_temporaries(const std::filesystem::path& directory,
                             std::string_view target_name = {});

/// Largest file read_file reads unless told otherwise [bytes]: history.csv, summary.json and
/// solution.pvd of even very long runs are far smaller.
constexpr std::uintmax_t kMaxReadBytes = std::uintmax_t{1} << 30;

/// The whole content of the file at `path`, for the readers of run-directory files (history,
/// collection, JSON, checkpoint). A run directory is user input to `plisse wrinkles DIR` and
/// restarts, so a missing or unreadable file, one that is not a regular file (a FIFO is refused,
/// not waited on) or one larger than `max_bytes` throws plisse::InputError (file = path, rule =
/// "cannot read: " followed by the reason).
std::string read_file(const std::filesystem::path& path, std::uintmax_t max_bytes = kMaxReadBytes);

/// Streams a file's content to a temporary file and puts it in place on `commit()`, for content
/// too large to hold twice in memory (VTU). Destroying an AtomicFile without a successful commit
/// removes the temporary file and leaves the target as it was. Not copyable; movable.
///
///   AtomicFile file(dir / "step_0001.vtu");
///   file.write(header);
///   file.write(bytes, n_bytes);
///   file.commit();
class AtomicFile {
 public:
  /// Creates the temporary file beside `target`. Throws plisse::Error (path, strerror) if it
  /// cannot, e.g. the directory is missing or not writable.
  explicit AtomicFile(std::filesystem::path target);
  ~AtomicFile();
  AtomicFile(AtomicFile&& other) noexcept;
  AtomicFile& operator=(AtomicFile&& other) noexcept;
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  /// Appends bytes (buffered). Precondition: not committed. Throws plisse::Error on a write error.
  void write(const void* data, std::size_t n_bytes);
  void write(std::string_view text) { write(text.data(), text.size()); }

  /// Flushes, closes and renames the temporary file over the target. After a successful commit
  /// the object is finished: further writes throw. Throws plisse::Error (path, strerror).
  void commit();

  const std::filesystem::path& target() const { return target_; }
  /// The temporary file being written (empty once committed or discarded).
  const std::filesystem::path& temporary() const { return temporary_; }

 private:
  void flush_buffer();
  void discard() noexcept;

  std::filesystem::path target_;
  std::filesystem::path temporary_;
  int fd_ = -1;
  std::string buffer_;  ///< pending bytes, written to fd_ when it passes kBufferBytes
  static constexpr std::size_t kBufferBytes = std::size_t{1} << 16;
};

/// Atomic replacement for writers that take a file name, not bytes (Gmsh's writer): they write
/// temporary(), a name beside the target that ends in the target's extension (for writers that
/// choose the format by extension: `.<name>.tmp.<pid>.<n>.msh`), and commit() renames it over the
/// target. Destroying an AtomicPath without a successful commit removes the temporary file.
///
///   AtomicPath file("mesh.msh");
///   write_gmsh(mesh, file.temporary().string());
///   file.commit();
class AtomicPath {
 public:
  explicit AtomicPath(std::filesystem::path target);
  ~AtomicPath();
  AtomicPath(const AtomicPath&) = delete;
  AtomicPath& operator=(const AtomicPath&) = delete;

  const std::filesystem::path& target() const { return target_; }
  /// The file to write (empty once committed).
  const std::filesystem::path& temporary() const { return temporary_; }
  /// Renames temporary() over the target. Throws plisse::Error (path, strerror) when the
  /// temporary file is missing or cannot be renamed; the target is then untouched.
  void commit();

 private:
  std::filesystem::path target_;
  std::filesystem::path temporary_;
};

}  // namespace plisse
