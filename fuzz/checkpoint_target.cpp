// Fuzz target "checkpoint": read_checkpoint, the reader of `plisse run --resume DIR`.
#include <cstring>

#include "core/error.hpp"
#include "output/checkpoint.hpp"
#include "scratch_file.hpp"
#include "targets.hpp"

namespace plisse::fuzz {
namespace {

bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * 8) == 0);
}

bool same(const Checkpoint& a, const Checkpoint& b) {
  if (!(a.fingerprint == b.fingerprint) || a.element != b.element || a.steps != b.steps ||
      !same_bits({a.time, a.dt, a.previous_dt}, {b.time, b.dt, b.previous_dt}) ||
      !same_bits(a.previous_state, b.previous_state) || !same_bits(a.state, b.state) ||
      !same_bits(a.bubbles, b.bubbles) || a.term_states.size() != b.term_states.size() ||
      a.negative_pivots != b.negative_pivots)
    return false;
  for (std::size_t k = 0; k < a.term_states.size(); ++k)
    if (!same_bits(a.term_states[k], b.term_states[k])) return false;
  return true;
}

}  // namespace

Outcome read_checkpoint_file(Bytes data) {
  const auto path = write_scratch_file("checkpoint.bin", data);
  Checkpoint c;
  try {
    c = read_checkpoint(path);
  } catch (const Error&) {  // InputError derives from Error
    return Outcome::rejected;
  }
  // What the reader accepts, the writer writes back to the same checkpoint.
  if (c.steps < 0 || c.state.empty() || !(c.dt > 0.0))
    throw Finding("accepted a checkpoint with a value out of range");
  write_checkpoint(path, c);
  if (!same(read_checkpoint(path), c))
    throw Finding("checkpoint does not read back identically after write_checkpoint");
  return Outcome::accepted;
}

}  // namespace plisse::fuzz
