#pragma once
/// Wall-clock timing of the phases of a run.
#include <chrono>

namespace plisse {

using WallClock = std::chrono::steady_clock;

/// Seconds of wall time since `start`.
inline double seconds_since(WallClock::time_point start) {
  return std::chrono::duration<double>(WallClock::now() - start).count();
}

}  // namespace plisse
