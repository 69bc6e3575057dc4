#pragma once
/// The test that gives a stalled Newton solve up early (NewtonSettings::stall_iterations): a solve
/// whose residual norm has crept down by less than 1 - stall_ratio per iteration for several
/// iterations in a row will, as a rule, not converge in the iterations left either, and each of
/// them costs a factorisation. The load stepper cuts the step back at once instead. Plain
/// arithmetic, no PETSc: NewtonSolver and ArcLengthSolver feed it their norms.
#include <string>

#include "solver/newton_settings.hpp"

namespace plisse {

class StallWatch {
 public:
  explicit StallWatch(const NewtonSettings& settings)
      : iterations_(settings.stall_iterations), ratio_(settings.stall_ratio) {}

  /// Forgets the norms seen: the next one is a solve's start.
  void restart();
  /// Takes ||R|| after an iteration (the first call after restart(): at the start). True once
  /// stall_iterations norms in a row each lay above stall_ratio times the one before; never
  /// when stall_iterations is 0.
  bool stalled(double norm);
  /// Why the solve was given up, in words, with the norms over the stalled run and the key.
  std::string describe() const;

 private:
  int iterations_ = 0;
  double ratio_ = 0.9;
  double previous_ = -1.0;  ///< the norm before, or < 0 at a solve's start
  int run_ = 0;             ///< stalled iterations in a row so far
  double run_start_ = 0.0;  ///< the norm before the first of them
};

}  // namespace plisse
