#pragma once
/// checkpoint.bin: what a run needs to continue after an interruption (`plisse run CASE --resume
/// DIR`): the stepping position and the last converged state. Binary, little-endian, written
/// atomically; a trailer detects truncation.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "element/element_family.hpp"

namespace plisse {

struct Checkpoint {
  std::uint64_t case_fingerprint = 0;            ///< of the case text and its --set overrides
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

/// FNV-1a (64 bit) of the case file's bytes followed by each override, so a checkpoint can only
/// resume the case (and overrides) that wrote it. Throws InputError if the file cannot be read.
std::uint64_t case_fingerprint(const std::filesystem::path& case_file,
                               const std::vector<std::string>& overrides);

/// Writes `c` to `path` atomically. Throws plisse::Error naming the path on failure.
void write_checkpoint(const std::filesystem::path& path, const Checkpoint& c);

/// Reads a checkpoint. Throws InputError (file = path, key "--resume") when it is missing,
/// truncated or not a plisse checkpoint.
Checkpoint read_checkpoint(const std::filesystem::path& path);

}  // namespace plisse
