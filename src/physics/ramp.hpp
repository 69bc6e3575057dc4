#pragma once
/// The time ramp of a load, a prescribed motion, a die or a cavity.
#include <algorithm>
#include <array>
#include <vector>

namespace plisse {

/// The factor a load's value is multiplied by at time t. Linear: 0 for t <= start, 1 for
/// t >= end, linear between (end > start >= 0); a load "held constant" after its ramp keeps
/// factor 1. Or a load curve: the points (t_i, f_i) of `table`, t_i strictly increasing, joined
/// linearly, f_0 before the first and the last f after the last (loading, holding, unloading and
/// cycles); start and end are then the first and last t_i.
struct Ramp {
  Ramp() = default;
  /// The linear ramp from `start` to `end`.
  Ramp(double start, double end) : start(start), end(end) {}

  double start = 0.0;                        ///< [s]
  double end = 1.0;                          ///< [s]; a case's default is its solver.end_time
  std::vector<std::array<double, 2>> table;  ///< (t [s], factor) points; empty: linear

  double factor(double t) const {
    if (!table.empty()) {
      if (t <= table.front()[0]) return table.front()[1];
      if (t >= table.back()[0]) return table.back()[1];
      const auto after = std::upper_bound(table.begin(), table.end(), t,
                                          [](double x, const auto& p) { return x < p[0]; });
      const auto& [t1, f1] = *after;
      const auto& [t0, f0] = *(after - 1);
      return f0 + (f1 - f0) * (t - t0) / (t1 - t0);
    }
    if (t <= start) return 0.0;
    if (t >= end) return 1.0;
    return (t - start) / (end - start);
  }

  bool operator==(const Ramp&) const = default;
};

}  // namespace plisse
