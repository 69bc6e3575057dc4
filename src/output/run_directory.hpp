#pragma once
/// The output directory of a run (`plisse run CASE -o DIR`) and the names of its files
/// (docs/architecture.md, "Interface contract"): history.csv, summary.json, solution.pvd with
/// step_NNNN.vtu, and log.txt. Files are written by output/history_writer, output/json_file,
/// output/pvd_writer with output/vtu_writer, and output/run_log.
#include <filesystem>
#include <string>
#include <vector>

#include "core/error.hpp"

namespace plisse {

class RunDirectory {
 public:
  /// Creates `directory` and its parents if missing, then checks that it is writable by creating
  /// and removing a probe file. Existing files in it are kept: whether an earlier run's files may
  /// be replaced is the caller's decision (run_files, remove_run_files). Throws plisse::InputError
  /// with place {file = directory as given, key = "-o"} and the reason (system message) if it
  /// cannot be created or written.
  explicit RunDirectory(const std::filesystem::path& directory);

  /// The directory (normalised, without a trailing '/').
  const std::filesystem::path& directory() const { return directory_; }
  std::filesystem::path history_csv() const { return directory_ / "history.csv"; }
  std::filesystem::path summary_json() const { return directory_ / "summary.json"; }
  std::filesystem::path solution_pvd() const { return directory_ / "solution.pvd"; }
  std::filesystem::path log_txt() const { return directory_ / "log.txt"; }
  /// directory() / step_file_name(step).
  std::filesystem::path step_vtu(int step) const { return directory_ / step_file_name(step); }

  /// "step_NNNN.vtu": the step number with at least 4 digits ("step_0007.vtu",
  /// "step_12345.vtu"); this relative name is what solution.pvd lists. Precondition: step >= 0
  /// (plisse::Error otherwise).
  static std::string step_file_name(int step);

 private:
  std::filesystem::path directory_;
};

/// The files of a run found in `directory` (sorted): history.csv, summary.json, solution.pvd,
/// log.txt, checkpoint.bin, wrinkle_spectrum.csv, wrinkles.json (plisse wrinkles) and the step
/// files step_N.vtu, step_N.pvtu and step_N_pR.vtu (N, R digits). Nothing else in the directory is
/// a run's, nor is a directory of one of these names.
std::vector<std::filesystem::path> run_files(const std::filesystem::path& directory);

/// Why a run could not write its files into `directory`, as far as can be seen without writing
/// (empty: nothing in the way): a component of the path that exists and is not a directory
/// ("cannot create the output directory: ..."), or a directory in it under the name of one of a
/// run's files (run_files, the lock file), which the run could neither write nor remove.
std::string output_path_problem(const std::filesystem::path& directory);

/// Removes run_files(directory) and the temporaries dead writers left there
/// (remove_stale_temporaries); other files are kept. Returns how many files were removed. Throws
/// plisse::Error naming the first file that cannot be removed.
int remove_run_files(const std::filesystem::path& directory);

/// The exclusive right to write into a directory, held by one process at a time: a `plisse run`
/// and `plisse wrinkles` take it for their whole run, so two of them never mix their files in one
/// directory. It is an flock(2) on the file `.plisse.lock` in the directory, which holds the
/// holder's process id and host; the kernel releases it when the holder dies, even by SIGKILL,
/// and the next holder reuses the file. The holder removes the file when it lets go.
class DirectoryLock {
 public:
  static constexpr const char* kFileName = ".plisse.lock";

  /// Takes the lock of `directory` (which must exist) without waiting. Throws InputError at
  /// `place` when another process holds it ("is in use by another plisse process (pid N on
  /// host H) ..."), when the lock file cannot be created or locked (the system's reason), and
  /// when the lock file or a name of run_files is a symbolic link (kSymbolicLinkRefusal): the
  /// holder writes no file through a link.
  DirectoryLock(const std::filesystem::path& directory, const InputPlace& place);
  /// Removes the lock file, then releases the lock.
  ~DirectoryLock();
  DirectoryLock(const DirectoryLock&) = delete;
  DirectoryLock& operator=(const DirectoryLock&) = delete;

 private:
  std::filesystem::path file_;
  int fd_ = -1;
};

}  // namespace plisse
