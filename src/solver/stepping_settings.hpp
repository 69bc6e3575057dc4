#pragma once
/// Settings of the load stepping (plain data, filled by the case reader from `solver:`).
#include "solver/newton_settings.hpp"

namespace plisse {

/// How a step's size is set: by its load increment (the time step), or by the length of its
/// increment along the path of equilibria (solver/arc_length.hpp).
enum class StepControl { load, arc_length };

/// Time runs from 0 to end_time in adaptive steps (solver/load_stepper.hpp).
struct SteppingSettings {
  StepControl control = StepControl::load;
  /// With arc-length control: the run ends, completed, when its load factor falls below this on a
  /// falling branch (past a limit load); 0: only end_time ends it.
  double stop_load_factor = 0.0;
  double end_time = 1.0;       ///< [s], > 0
  int steps = 10;              ///< initial number of steps (initial step = end_time/steps), >= 1
  int max_steps = 10000;       ///< >= 1
  double min_step = 1e-8;      ///< smallest step as a fraction of end_time, in (0, 1]
  double max_step = 1.0;       ///< largest step as a fraction of end_time, in (0, 1]
  double growth = 1.5;         ///< step growth after easy steps, >= 1
  double cutback = 0.5;        ///< step reduction after a failure, in (0, 1)
  int easy_iterations = 4;     ///< a step is easy when Newton takes at most this many iterations
  int max_augmentations = 20;  ///< multiplier updates per step (augmented Lagrangian contact)
  NewtonSettings newton;
};

}  // namespace plisse
