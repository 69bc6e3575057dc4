#pragma once
/// checkpoint.bin: what a run needs to continue after an interruption (`plisse run CASE --resume
/// DIR`): the stepping position and the last converged state. Binary, little-endian, written
/// atomically; a trailer detects truncation.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "element/element_family.hpp"
#include "mesh/mesh.hpp"

namespace plisse {

/// What a checkpoint belongs to: the case file's bytes, the --set values and the mesh file's
/// bytes, so a resume can say which of them changed.
struct RunFingerprint {
  std::uint64_t case_text = 0;         ///< FNV-1a (64 bit) of the case file's bytes
  std::vector<std::string> overrides;  ///< the --set values, in order
  /// `mesh.file` as an absolute path, for messages only (the same file may be named otherwise from
  /// another working directory); empty for a generated mesh
  std::string mesh_file;
  std::uint64_t mesh_bytes = 0;  ///< FNV-1a of the mesh file's bytes (0: generated mesh)
  /// geometry_hash of the mesh the run solves on: after an imperfection and the snapping to
  /// symmetry planes, so a changed mode file or generator is seen too.
  std::uint64_t geometry = 0;

  bool operator==(const RunFingerprint&) const = default;
};

/// The fingerprint of a run of `case_file` with `overrides` on `mesh_file` (empty: a generated
/// mesh), solving on `mesh`. Reads both files through; throws InputError if one cannot be read.
RunFingerprint run_fingerprint(const std::filesystem::path& case_file,
                               const std::vector<std::string>& overrides,
                               const std::string& mesh_file, const Mesh& mesh);

/// Empty when `now` is the run `saved` belongs to; otherwise what differs, in words: "the case
/// file changed since the checkpoint was written", "the --set values differ (checkpoint: a, b;
/// now: a, c)", "the mesh file M changed ...", "the mesh's nodes or tetrahedra differ ...",
/// joined by "; ". A mesh file is compared by its content (mesh_bytes), never by the spelling of
/// its path.
std::string fingerprint_changes(const RunFingerprint& saved, const RunFingerprint& now);

struct Checkpoint {
  RunFingerprint fingerprint;                    ///< the run it belongs to
  ElementFamily element = ElementFamily::mini;   ///< the element of the run
  int steps = 0;                                 ///< converged steps
  double time = 0.0;                             ///< of the last converged step [s]
  double dt = 0.0;                               ///< next step size
  double previous_dt = 0.0;                      ///< last step size
  std::vector<double> previous_state;            ///< converged state before the last one
  std::vector<double> state;                     ///< last converged full state
  std::vector<double> bubbles;                   ///< elements' internal state (MINI: bubbles)
  std::vector<std::vector<double>> term_states;  ///< per model term (contact history ...)
  int negative_pivots = -1;  ///< stability check: of the last converged step (-1: not checked)
};

/// Writes `c` to `path` atomically. Throws plisse::Error naming the path on failure.
void write_checkpoint(const std::filesystem::path& path, const Checkpoint& c);

/// Reads a checkpoint. Throws InputError (file = path, key "--resume") when it is missing, not a
/// regular file, truncated, damaged (checksum), not a plisse checkpoint of this version, or holds
/// a value out of its range: a negative step count, a non-finite or negative time, a step size
/// that is not finite and positive, a non-finite state value, arrays of inconsistent sizes.
Checkpoint read_checkpoint(const std::filesystem::path& path);

}  // namespace plisse
