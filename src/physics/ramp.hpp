#pragma once
/// The time ramp of a load, a prescribed motion, a die or a cavity.
namespace plisse {

/// Linear time ramp: factor 0 for t <= start, 1 for t >= end, linear between (end > start >= 0).
/// A load "held constant" after its ramp keeps factor 1.
struct Ramp {
  double start = 0.0;  ///< [s]
  double end = 1.0;    ///< [s]; a case's default is its solver.end_time
  double factor(double t) const {
    if (t <= start) return 0.0;
    if (t >= end) return 1.0;
    return (t - start) / (end - start);
  }
};

}  // namespace plisse
