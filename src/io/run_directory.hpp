#pragma once
/// The output directory of a run (`plisse run CASE -o DIR`) and the names of its files
/// (docs/architecture.md, "Interface contract"): history.csv, summary.json, solution.pvd with
/// step_NNNN.vtu, and log.txt. Files are written by io/history_writer, io/json_file,
/// io/pvd_writer with io/vtu_writer, and io/run_log.
#include <filesystem>
#include <string>

namespace plisse {

class RunDirectory {
 public:
  /// Creates `directory` and its parents if missing, then checks that it is writable by creating
  /// and removing a probe file. Existing files in it are kept (they are replaced as the run
  /// writes its own). Throws plisse::InputError with place {file = directory as given,
  /// key = "-o"} and the reason (system message) if it cannot be created or written.
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

}  // namespace plisse
