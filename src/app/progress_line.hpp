#pragma once
/// The progress line `plisse run` prints (and writes to log.txt) after every converged step.
#include <string>
#include <vector>

#include "analysis/wrinkle_lines.hpp"
#include "analysis/wrinkle_rings.hpp"
#include "solver/load_stepper.hpp"

namespace plisse::app {

/// Where the run stands in time, for the estimate of the time left.
struct ProgressClock {
  double elapsed = 0.0;     ///< wall time since the run started [s] (the line's `elapsed`)
  double stepping = 0.0;    ///< wall time since this process started stepping [s]
  double start_time = 0.0;  ///< the model time stepping started from (a resume's checkpoint) [s]
  double end_time = 1.0;    ///< solver.end_time [s]
  /// Arc-length control: the load factor may fall, so its rate says nothing of the time left.
  bool arc_length = false;
};

/// The wrinkled ring or line of the largest amplitude: rings only when the report is wrinkled,
/// lines when they are; at most one of the two is set, neither when nothing is wrinkled. What the
/// progress line and a run's first_wrinkled name.
struct LargestWrinkle {
  const RingMetrics* ring = nullptr;
  const LineReading* line = nullptr;
};
LargestWrinkle largest_wrinkle(const WrinkleReport* rings, const std::vector<LineReading>* lines);

/// "step 12  t 0.24  load 0.2400  dt 0.02  newton  6  reuse  4  |R| 1.017e-12  stable  elapsed
/// 26.0s  left ~1m50s", with, when they apply, "cut-backs N" (failed attempts of this step), the
/// stability state ("UNSTABLE (3/2 neg. pivots)", "SINGULAR (1 zero pivot)") and the wrinkles
/// ("wrinkled (ring 30 deg: 12 waves, 0.0123 mm)" or "wrinkled (line gen: 14 crests, 0.061 mm)",
/// the ring or line of the largest amplitude). `newton` counts every Newton iteration of the
/// accepted attempt, contact passes included; `wrinkles` and `lines` may be null (no rings or
/// lines measured). The time left is the wall time per unit of model time so far,
/// times the model time still to go; none before the first step or after the last, and "left
/// unknown (steps cut back)" after a step that needed cut-backs.
std::string progress_line(const StepInfo& info, const WrinkleReport* wrinkles,
                          const ProgressClock& clock,
                          const std::vector<LineReading>* lines = nullptr);

/// A duration for people: "42s", "3m05s", "2h07m".
std::string format_duration(double seconds);

}  // namespace plisse::app
