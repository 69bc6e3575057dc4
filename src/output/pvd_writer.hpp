#pragma once
/// ParaView collection file (solution.pvd): the list of (time, VTU file) of a run, so ParaView
/// shows the steps on a time axis. Format: VTKFile type="Collection" with one
/// <DataSet timestep=".." group="" part="0" file=".."/> per entry.
///
/// The whole file is rewritten atomically on each add(), so it is valid after every step even if
/// the run is killed.
#include <filesystem>
#include <string>
#include <vector>

namespace plisse {

/// One step of a collection.
struct PvdEntry {
  double time = 0.0;  ///< [s], the case's time (load ramps are functions of it)
  std::string file;   ///< relative to the directory of the .pvd file, '/' separated
};

class PvdWriter {
 public:
  /// Starts the collection at `path` (e.g. DIR/solution.pvd) with `entries` (empty for a new
  /// run, those of read_pvd() for a restart) and writes it at once. Throws plisse::Error naming
  /// the path if it cannot be written.
  explicit PvdWriter(std::filesystem::path path, std::vector<PvdEntry> entries = {});

  /// Appends (time, file) and rewrites the collection. `file` must be relative to the
  /// collection's directory (it is written as given, e.g. "step_0007.vtu"); `time` must be
  /// finite. Throws plisse::Error on a violated precondition or a write failure.
  void add(double time, const std::string& file);

  const std::filesystem::path& path() const { return path_; }
  const std::vector<PvdEntry>& entries() const { return entries_; }

 private:
  void write() const;

  std::filesystem::path path_;
  std::vector<PvdEntry> entries_;
};

/// The entries of a collection written by PvdWriter (for a restart). Throws plisse::InputError
/// (file = path) if the file cannot be read or is not such a collection.
std::vector<PvdEntry> read_pvd(const std::filesystem::path& path);

}  // namespace plisse
