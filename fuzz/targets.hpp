#pragma once
/// Fuzz targets: plisse's readers of user files, each wrapped as a function of raw bytes.
///
/// The same functions are driven by libFuzzer (libfuzzer_main.cpp, PLISSE_FUZZ builds) and by the
/// unit test that replays fuzz/regressions/ and fuzz/corpus/ in every build (regression_test.cpp),
/// so a fixed crash stays fixed.
///
/// Contract of a target: bad input is rejected with plisse::InputError or plisse::Error (the target
/// returns Outcome::rejected); anything else (another exception type, a crash, a sanitizer report,
/// a violated postcondition, reported as Finding) is a bug.
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>

namespace plisse::fuzz {

using Bytes = std::span<const std::uint8_t>;

enum class Outcome { accepted, rejected };

/// A property every input must satisfy failed. Deliberately not a plisse::Error, so that no target
/// mistakes it for a rejection of bad input.
class Finding : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

/// parse_case_string on the bytes as a case file named "fuzz.yaml". Lines of the form
/// "#set key.path=value" (YAML comments) are also passed as `--set` overrides, in order, so the
/// override parser is fuzzed through the same input.
Outcome parse_case(Bytes data);

/// read_gmsh on the bytes written to a temporary ".msh" file, with tighter limits for its reader
/// process than a user's file gets (Gmsh itself runs in that process: what crashes or exhausts it
/// is a rejected input). Gmsh is one global state: after each input the target checks that the
/// reader left nothing behind in this process (no model entities, no views, no pending log), and
/// every kReferenceEvery-th input re-reads a reference mesh that must come back identical.
/// Accepted meshes must satisfy read_gmsh's postconditions (indices in range).
Outcome read_mesh(Bytes data);

/// read_history on the bytes written to a temporary history.csv; an accepted plisse history
/// (HistoryWriter::reopen) is rewritten and read back, and must reproduce every value bit for bit
/// (NaN as NaN).
Outcome read_history_file(Bytes data);

/// read_checkpoint on the bytes written to a temporary checkpoint.bin; an accepted checkpoint is
/// written back with write_checkpoint and must read back bit for bit.
Outcome read_checkpoint_file(Bytes data);

/// read_vtu_summary and every point and cell field of the bytes written to a temporary ".vtu"
/// file (raw or zlib-compressed); an accepted file's fields hold exactly the values its header
/// declares.
Outcome read_vtu_file(Bytes data);

/// A target by name: "case", "gmsh", "history", "checkpoint" or "vtu" (the folder names under
/// fuzz/corpus/ and fuzz/regressions/). Returns nullptr for an unknown name.
using TargetFunction = Outcome (*)(Bytes);
TargetFunction find_target(const std::string& name);

}  // namespace plisse::fuzz
