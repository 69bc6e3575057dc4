#pragma once
/// The run recorder: everything a run leaves in its run directory besides the log. It owns
/// history.csv (rows from HistoryColumns), the VTU files with solution.pvd, wrinkle_spectrum.csv,
/// checkpoint.bin and summary.json, and decides when each is written (the checkpoint's cadence
/// included). Distributed runs: rank 0
/// writes the history, the PVD index, the checkpoint and the summary; every rank writes its own
/// piece of each VTU step. The members that write are collective: every rank calls them in the same
/// order.
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "app/history_columns.hpp"
#include "app/wrinkling.hpp"
#include "case/case.hpp"
#include "core/wall_clock.hpp"
#include "material/material_fit.hpp"
#include "output/checkpoint.hpp"
#include "output/history_writer.hpp"
#include "output/pvd_writer.hpp"
#include "output/run_directory.hpp"
#include "solver/load_stepper.hpp"
#include "solver/mixed_model.hpp"

namespace plisse::app {

/// What identifies a run in its summary and checkpoint.
struct RunIdentity {
  std::string case_file;               ///< as given on the command line
  std::vector<std::string> overrides;  ///< --set values
  RunFingerprint fingerprint;          ///< of the case, the --set values and the mesh file
};

/// Wall times measured before the recorder exists.
struct StartTimes {
  WallClock::time_point start;  ///< the run's start
  double mesh = 0.0;            ///< reading or generating the mesh [s]
  double setup = 0.0;           ///< model, stepper and wrinkle meter [s]
};

class RunRecorder {
 public:
  /// Borrows everything (all must outlive the recorder). Opens the run's files in `directory`:
  /// a new history.csv and solution.pvd, or with `resume` (the checkpoint the model and stepper
  /// were restored from) the existing ones cut back to the checkpoint's step. Throws InputError
  /// (key --resume) when the history does not match the checkpoint. `meter` is required when the
  /// case measures wrinkles.
  RunRecorder(const Case& c, const RunDirectory& directory, RunIdentity identity,
              const MixedModel& model, const LoadStepper& stepper, const WrinkleMeter* meter,
              const Checkpoint* resume);

  /// Writes step_0000.vtu, the state before the first step (t = 0: the undeformed body, zero
  /// reactions), and lists it first in solution.pvd. For a new run, before the stepping.
  void record_initial_state();
  /// Records one converged step (the model holds its state): the history row, the wrinkle
  /// metrics, an instability's record, and the VTU file every output.every steps, at the end of
  /// the load and at a new instability (its modes seed `imperfection_kind: mode`).
  void record(const StepInfo& info);
  /// Writes checkpoint.bin from the model and stepper's last converged state.
  void save_checkpoint();
  /// The checkpoint cadence, after recording the converged step `step`: writes checkpoint.bin
  /// every output.checkpoint_every steps, and when output.checkpoint_minutes have passed since
  /// the last checkpoint (or since the recorder started, or wrote the initial state), decided on
  /// every rank alike. A run stopped by a signal or a solver failure is checkpointed by finish.
  void checkpoint_when_due(int step);
  /// After the stepping: the last step's VTU if it is not written yet, the final checkpoint (the
  /// state `plisse wrinkles DIR` reads) and summary.json. Returns the job's peak memory [MiB].
  double finish(const SteppingResult& result, const StartTimes& times);

  /// The last recorded step (step 0 before any).
  const StepInfo& last_step() const { return last_step_; }
  /// The load columns of the last recorded step's history row (pressures `pressure:`, dead and
  /// follower loads `load_x:` ..., caps' and dies' forces and moments `force_x:`, `moment_x:`
  /// ...), in the history's order; empty before any step. What a run stopped at a limit load names.
  std::vector<std::pair<std::string, double>> last_loads() const;
  /// The wrinkle metrics of the last recorded step, when the case measures them.
  const std::optional<WrinkleMeter::Result>& last_wrinkles() const { return last_wrinkles_; }
  /// The notice of the first recorded step at which a ring or line is wrinkled (what, how much,
  /// and whether the stability check found every step so far stable), once; empty otherwise.
  std::string take_wrinkle_notice() { return std::exchange(wrinkle_notice_, ""); }
  /// Time spent computing and writing output so far [s].
  double output_seconds() const { return output_seconds_; }

  /// A material whose stability (Drucker) the run watches: an isotropic model whose stable
  /// stretch range (material/material_fit.hpp) ends inside [0.1, 10] in the uniaxial,
  /// equibiaxial or planar test. Every recorded step checks Drucker's condition at the state of
  /// each element of it (its mean deformation's principal stretches).
  struct WatchedMaterial {
    std::string region;  ///< the region's label (volume tag); empty for the case's `material`
    AnyMaterial material;
    std::vector<StabilityRange> ranges;  ///< per test
  };
  /// The watched materials; empty when every material is stable over all of [0.1, 10].
  const std::vector<WatchedMaterial>& watched_materials() const { return watched_; }
  /// The warning of the first recorded step with an element where the material is not stable,
  /// once; empty otherwise.
  std::string take_material_warning();

 private:
  /// The VTU file of `info`'s step, whose state the model holds; `step_start` is the state at the
  /// start of that step (for the step velocity).
  void write_step_files(const StepInfo& info, const std::vector<double>& step_start);
  /// Records the first wrinkled step (summary.json first_wrinkled) and its notice.
  void note_first_wrinkled(const StepInfo& info);
  /// A resumed run's first wrinkled step and stability so far, from the history's kept rows.
  void read_wrinkling_so_far();
  /// Drucker's condition at every element's state; the warning at the first failure.
  void check_material_stability(int step);
  nlohmann::json summary(const SteppingResult& result, const StartTimes& times, double memory_total,
                         double memory_largest) const;
  /// summary.json's material_stability: the first step and counts of unstable elements, and the
  /// stable stretch ranges of each watched material.
  nlohmann::json material_stability() const;

  const Case& case_;
  const RunDirectory& directory_;
  RunIdentity identity_;
  const MixedModel& model_;
  const LoadStepper& stepper_;
  const WrinkleMeter* meter_;
  bool root_;
  HistoryColumns columns_;
  std::optional<HistoryWriter> history_;  ///< rank 0's
  std::optional<PvdWriter> pvd_;          ///< rank 0's
  /// Rank 0's wrinkle_spectrum.csv, when the case measures rings: a block per written step.
  std::optional<WrinkleSpectrumWriter> spectrum_;
  /// Element fields (stress, J) of the last recorded step: computed once per step for the
  /// history, the wrinkle metrics and the VTU file.
  std::vector<ElementFields> fields_;
  /// A shell's outputs of the last recorded step (thickness, resultants, faces), for the history
  /// and the VTU file; empty for solid elements.
  std::vector<shell::ShellOutputs> shell_outputs_;
  std::vector<double> previous_state_;   ///< state at the end of the last recorded step
  std::vector<double> last_step_start_;  ///< state at the start of the last recorded step
  std::optional<WrinkleMeter::Result> last_wrinkles_;
  nlohmann::json instabilities_ = nlohmann::json::array();
  StepInfo last_step_;
  std::vector<double> last_row_;  ///< the last recorded step's history row
  /// The time of the resumed checkpoint (0 for a fresh run): a resumed run that has no step
  /// left records no step, and its summary's final_time is this one.
  double start_time_ = 0.0;
  std::vector<WatchedMaterial> watched_;
  /// Per material index of the case's sections (the case's `material`, then the deformable
  /// regions'): its entry in watched_, or -1.
  std::vector<int> watch_of_material_;
  /// The step files' `material` cell field, made once; empty for a case without regions.
  std::vector<double> material_field_;
  int first_unstable_step_ = -1;    ///< the first recorded step with an unstable element
  int unstable_elements_ = 0;       ///< at the last recorded step
  int most_unstable_elements_ = 0;  ///< over the recorded steps
  std::string material_warning_;
  /// summary.json's first_wrinkled: null until a ring or line is wrinkled.
  nlohmann::json first_wrinkled_;
  /// The stability check has found every recorded step stable (true without the check).
  bool stable_so_far_ = true;
  std::string wrinkle_notice_;
  int last_written_ = -1;
  int accepted_newton_iterations_ = 0;  ///< over the steps recorded by this run
  double output_seconds_ = 0.0;
  WallClock::time_point last_checkpoint_;  ///< of the wall-time cadence
};

}  // namespace plisse::app
