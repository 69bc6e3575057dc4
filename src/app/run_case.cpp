#include "app/run_case.hpp"

#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "analysis/point_location.hpp"
#include "app/model_builder.hpp"
#include "app/pre_step_checks.hpp"
#include "app/progress_line.hpp"
#include "app/run_plan.hpp"
#include "app/run_recorder.hpp"
#include "app/run_session.hpp"
#include "app/wrinkling.hpp"
#include "case/case.hpp"
#include "core/error.hpp"
#include "core/wall_clock.hpp"
#include "mesh/topology.hpp"
#include "output/atomic_file.hpp"
#include "output/checkpoint.hpp"
#include "output/run_directory.hpp"
#include "output/run_log.hpp"
#include "solver/collective.hpp"
#include "solver/linear_solver.hpp"
#include "solver/load_stepper.hpp"
#include "solver/petsc_call.hpp"
#include "solver/petsc_session.hpp"

namespace plisse::app {
namespace {

namespace fs = std::filesystem;

/// The mesh the run solves on, the seconds its reading or generation took, and the run's
/// fingerprint (of the case file, the --set values and the mesh).
struct RunMesh {
  Mesh mesh;
  double seconds = 0.0;
  RunFingerprint fingerprint;
};

/// Reads or generates the case's mesh and refuses what this build cannot solve on it.
RunMesh load_run_mesh(const Case& c, const RunOptions& options) {
  const auto t0 = WallClock::now();
  RunMesh run_mesh{load_perturbed_mesh(c), 0.0, {}};
  run_pre_step_checks(PreStepStage::mesh, c, run_mesh.mesh);
  run_mesh.seconds = seconds_since(t0);
  // After the mesh file has passed its reader's checks (type, size): it is hashed whole.
  run_mesh.fingerprint = run_fingerprint(options.case_file, options.overrides,
                                         c.mesh.file.value_or(""), run_mesh.mesh);
  return run_mesh;
}

/// Every rank builds the mesh on its own (reads or generates it); they must agree, node for node.
void check_same_mesh_on_every_rank(const Mesh& mesh) {
  if (PetscSession::size() == 1) return;
  unsigned long long low = geometry_hash(mesh), high = low;
  PLISSE_PETSC(
      MPI_Allreduce(MPI_IN_PLACE, &low, 1, MPI_UNSIGNED_LONG_LONG, MPI_MIN, PETSC_COMM_WORLD));
  PLISSE_PETSC(
      MPI_Allreduce(MPI_IN_PLACE, &high, 1, MPI_UNSIGNED_LONG_LONG, MPI_MAX, PETSC_COMM_WORLD));
  if (low != high)
    throw Error(
        "the ranks built different meshes from the same case (mesh generation is not "
        "reproducible here); write the mesh once with `plisse mesh` and use mesh.file");
}

/// What every step of the driver reads: the options, the case, the plan, the mesh, the session
/// and the run's start (all borrowed from run_case).
struct RunContext {
  const RunOptions& options;
  const Case& c;
  const RunPlan& plan;
  const RunMesh& mesh;
  const RunSession& session;
  WallClock::time_point start;
};

/// What solves the case: the model, its load stepper and, when the case measures wrinkles, the
/// wrinkle meter. Needs a live RunSession.
struct RunSolver {
  RunSolver(const Case& c, const Mesh& mesh, ModelParts parts)
      : n_constrained(parts.constraints.size()),
        model(make_run_model(c, mesh, std::move(parts), factor_ordering)),
        stepper(*model, c.solver) {
    stepper.set_stability(stability_check_settings(c));
    if (c.output.wrinkles.enabled()) wrinkle_meter.emplace(c, mesh);
  }
  /// The model, with MUMPS's options set before the stepper's solvers read them; `ordering`
  /// becomes the shell's chosen ordering (choose_factor_ordering), or stays -1.
  static std::unique_ptr<MixedModel> make_run_model(const Case& c, const Mesh& mesh,
                                                    ModelParts parts, int& ordering) {
    // A rigid cap borders the tangent with one multiplier per tied component: MUMPS needs more
    // working space than it estimates (linear_solver.hpp, request_factor_workspace).
    if (!c.terms_in("caps").empty()) request_factor_workspace(100);
    std::unique_ptr<MixedModel> model = make_model(mesh, std::move(parts));
    if (mesh.is_shell()) ordering = choose_factor_ordering(*model);
    return model;
  }
  std::size_t n_constrained;  ///< constrained components of the model
  int factor_ordering = -1;   ///< MUMPS's ICNTL(7) chosen for a shell, else -1
  std::unique_ptr<MixedModel> model;
  LoadStepper stepper;
  std::optional<WrinkleMeter> wrinkle_meter;
};

/// The run directory, this run's alone while it runs, with the run's log (rank 0's writes
/// log.txt, the other ranks' write nowhere). Collective.
class RunOutput {
 public:
  /// Takes the directory's lock and applies the plan: a directory in use, or holding an earlier
  /// run that the plan refuses to replace, is refused (InputError at the directory, key --resume
  /// or -o; rank 0 decides for all). Then removes the earlier run's files (--overwrite) or the
  /// temporaries a killed run left, and starts the log (a resumed run appends to its log.txt).
  explicit RunOutput(const RunPlan& plan) : directory_(plan.directory) {
    const bool root = PetscSession::rank() == 0;
    const InputPlace place{directory_.directory().string(), 0, 0, plan.directory_key};
    std::string refusal;
    if (root) {
      try {
        lock_.emplace(directory_.directory(), place);
        if (plan.refuse_earlier_run) refusal = earlier_run_refusal(directory_.directory());
        if (refusal.empty()) refusal = resumed_checkpoint_refusal(plan);
      } catch (const InputError& e) {
        refusal = e.rule();
      }
    }
    refusal = from_root(refusal);
    if (!refusal.empty()) throw InputError(place, refusal);
    // The earlier run's files themselves are whole (atomic writes and whole-line appends).
    // Rank 0's files: a failure there is agreed by all ranks, which then unwind together.
    on_every_rank_alike([&] {
      if (!root) return;
      removed_ = plan.overwrite ? remove_run_files(directory_.directory())
                                : remove_stale_temporaries(directory_.directory());
      log_.emplace(directory_.log_txt(), plan.resume ? LogStart::append : LogStart::replace);
    });
    if (!root) log_.emplace(fs::path{}, nullptr, nullptr);
  }

  const RunDirectory& directory() const { return directory_; }
  RunLog& log() { return *log_; }
  /// Appends the new log lines to log.txt (collective: a failed write is agreed by all ranks).
  void flush_log() {
    on_every_rank_alike([&] { log_->flush(); });
  }
  /// The files removed when the directory was taken (rank 0; 0 on the other ranks).
  int removed() const { return removed_; }

 private:
  RunDirectory directory_;
  std::optional<DirectoryLock> lock_;  ///< rank 0's
  std::optional<RunLog> log_;
  int removed_ = 0;
};

/// The log's lines about the input: the case, the output directory, the sizes, the threads, the
/// warnings, where the point loads and probes sit.
void log_input(RunLog& log, const RunContext& run, const RunOutput& out, const RunSolver& solver) {
  const Case& c = run.c;
  const Mesh& mesh = run.mesh.mesh;
  const MixedModel& model = *solver.model;
  log.info("plisse run " + run.options.case_file + (c.title.empty() ? "" : "  (" + c.title + ")"));
  log.info("output: " + out.directory().directory().string());
  for (const auto& o : run.options.overrides) log.info("  --set " + o);
  char line[256];
  std::snprintf(line, sizeof line,
                "mesh: %d nodes, %d %s (%s); unknowns: %d (%d pressure), %zu constrained",
                mesh.n_nodes(), model.n_elements(), mesh.is_shell() ? "triangles" : "tetrahedra",
                to_string(model.element_family()).c_str(), model.n_free(),
                model.dofs().n_free_pressure(), solver.n_constrained);
  log.info(line);
  if (const int twins = model.pressure_twins().n_twins(); twins > 0)
    log.info("regions: a pressure of each region's own at the " + std::to_string(twins) +
             " corner nodes where they meet (" + std::to_string(twins) +
             " pressure unknowns more; region_pressure: continuous shares one field)");
  log.info("threads: " + run.session.threads());
  if (solver.factor_ordering >= 0)
    log.info(std::string("factorisations: ordered by ") +
             (solver.factor_ordering == 0 ? "approximate minimum degree" : "MUMPS's own choice") +
             " (-mat_mumps_icntl_7 " + std::to_string(solver.factor_ordering) +
             "), estimated by MUMPS's analysis of the first tangent to need fewer operations "
             "than the other; a -mat_mumps_icntl_7 given for a solver overrides it");
  log.info(
      "units: the case's, consistent (mm, N, MPa, s in plisse's docs); history.csv's "
      "columns: summary.json history_units, plisse outputs");
  for (const InputError& e : setup_warnings(c, &mesh)) log.warn(e.what());
  for (const TermEntry& entry : c.terms)
    for (const std::string& note : entry.kind->notes(entry, mesh)) log.info(note);
  for (const Probe& probe : c.probes) {
    const MeshPoint at = locate_point(mesh, probe.point);
    std::snprintf(line, sizeof line,
                  "probe '%s': %s element %d at [%.6g, %.6g, %.6g], %.3g mm from its point",
                  probe.name.c_str(), at.inside ? "in" : "on the surface of", at.element,
                  at.position.x(), at.position.y(), at.position.z(), at.distance);
    log.info(line);
  }
}

/// The log's line on the split of the work among the ranks of a distributed run. Collective.
void log_distribution(RunLog& log, const MixedModel& model) {
  if (model.n_ranks() == 1) return;
  // Each rank evaluates the elements touching its nodes: the cut elements twice.
  const int owned = model.n_owned(), n_elements = model.n_elements();
  int most = owned, fewest = owned, evaluated = static_cast<int>(model.local_elements().size());
  PLISSE_PETSC(MPI_Allreduce(MPI_IN_PLACE, &most, 1, MPI_INT, MPI_MAX, PETSC_COMM_WORLD));
  PLISSE_PETSC(MPI_Allreduce(MPI_IN_PLACE, &fewest, 1, MPI_INT, MPI_MIN, PETSC_COMM_WORLD));
  PLISSE_PETSC(MPI_Allreduce(MPI_IN_PLACE, &evaluated, 1, MPI_INT, MPI_SUM, PETSC_COMM_WORLD));
  char line[256];
  std::snprintf(line, sizeof line,
                "distributed over %d ranks: %d to %d unknowns per rank; %d element "
                "evaluations per assembly for %d elements (+%.1f %%)",
                model.n_ranks(), fewest, most, evaluated, n_elements,
                100.0 * (evaluated - n_elements) / std::max(1, n_elements));
  log.info(line);
}

/// The log's opening lines, and what taking the directory removed. Collective.
void log_header(const RunContext& run, RunOutput& out, const RunSolver& solver) {
  log_input(out.log(), run, out, solver);
  log_distribution(out.log(), *solver.model);
  if (out.removed() > 0)
    out.log().info("removed " + std::to_string(out.removed()) +
                   (run.plan.overwrite ? " file(s) of the earlier run (--overwrite)"
                                       : " temporary file(s) an interrupted run left"));
}

/// A resumed run: the model and the stepper continue from the checkpoint. A checkpoint the model
/// cannot take is an InputError at the directory's checkpoint.bin (key --resume).
void restore_checkpoint(const RunPlan& plan, const RunDirectory& directory, RunSolver& solver) {
  if (!plan.resume) return;
  const Checkpoint& checkpoint = *plan.resume;
  try {
    solver.model->restore({checkpoint.state, checkpoint.bubbles, checkpoint.term_states});
  } catch (const InputError&) {
    throw;
  } catch (const Error& e) {
    throw InputError({(directory.directory() / "checkpoint.bin").string(), 0, 0, "--resume"},
                     e.what());
  }
  solver.stepper.resume({checkpoint.steps, checkpoint.time, checkpoint.dt, checkpoint.previous_dt,
                         checkpoint.previous_state, checkpoint.negative_pivots});
}

/// Where the stepping starts: a second step (--from) from the earlier run's last state, a
/// resumed run after its checkpoint's step, a new run from the initial state, which the recorder
/// writes. Then the log's lines on the watched materials.
void set_start(const RunContext& run, RunSolver& solver, RunRecorder& recorder, RunLog& log) {
  if (const std::optional<Checkpoint>& from = run.plan.from) {
    // A second load step: the nodal values and the elements' internal state carry over; the
    // terms (loads, cavities, dies, contacts, caps) and the clock start afresh from this case.
    // (Their number was checked before the run directory was taken.)
    solver.model->continue_from(from->state, from->bubbles);
    log.info("starting from the last state of " + run.plan.from_directory + " (step " +
             std::to_string(from->steps) + " at t = " + std::to_string(from->time) +
             "); this case's time starts at 0");
    if (!run.plan.from_unfinished.empty())
      log.warn("--from-unfinished: the run in " + run.plan.from_directory + " " +
               run.plan.from_unfinished +
               "; this run starts from its last checkpoint, not from "
               "the end of its loading");
  }
  if (const std::optional<Checkpoint>& resume = run.plan.resume)
    log.info("resuming after step " + std::to_string(resume->steps) +
             " at t = " + std::to_string(resume->time));
  else
    recorder.record_initial_state();
  for (const RunRecorder::WatchedMaterial& w : recorder.watched_materials()) {
    std::ostringstream line;
    line.precision(3);
    line << (w.region.empty() ? "material" : "region " + w.region + " material")
         << ": stable (Drucker) for stretches";
    for (const StabilityRange& r : w.ranges)
      line << ' ' << test_mode_name(r.mode) << ' ' << r.lower << " to " << r.upper;
    line << "; every step checks each element, and the log warns at the first that is not";
    log.info(line.str());
  }
}

/// Steps to the end time. Every converged step is recorded, logged with its progress line and
/// checkpointed when due (RunRecorder::checkpoint_when_due). SIGINT/SIGTERM stop the stepper
/// before the next step or within the current one (Newton iterations, cut-backs, multiplier
/// updates); the model is back at the last converged step, whose checkpoint the recorder's
/// finish writes.
SteppingResult step_to_the_end(const RunContext& run, RunSolver& solver, RunRecorder& recorder,
                               RunOutput& out) {
  RunLog& log = out.log();
  const WallClock::time_point stepping_start = WallClock::now();
  const double start_time = run.plan.resume ? run.plan.resume->time : 0.0;
  const auto on_step = [&](const StepInfo& info) {
    recorder.record(info);
    if (const std::string w = recorder.take_material_warning(); !w.empty()) log.warn(w);
    if (const std::string w = recorder.take_wrinkle_notice(); !w.empty()) log.info(w);
    const auto& wrinkles = recorder.last_wrinkles();
    log.info(progress_line(info, wrinkles ? &wrinkles->rings : nullptr,
                           {seconds_since(run.start), seconds_since(stepping_start), start_time,
                            run.c.solver.end_time, run.c.solver.control == StepControl::arc_length},
                           wrinkles ? &wrinkles->lines : nullptr));
    recorder.checkpoint_when_due(info.step);
    out.flush_log();
  };
  solver.stepper.set_interrupt([&] { return run.session.interrupt_requested(); });
  const SteppingResult result =
      solver.stepper.run(on_step, [&](const std::string& s) { log.warn(s); });
  if (result.interrupted)
    log.warn("interrupted by a signal during step " + std::to_string(result.steps + 1) +
             ": stopping; the checkpoint holds step " + std::to_string(result.steps));
  return result;
}

/// What a run stopped at its smallest step says of the load it reached (load_stepper's
/// smallest_step): the load factor and time of the last converged step, the loads there (the
/// history's load columns: RunRecorder::last_loads), and how to go past it. Under arc-length
/// control (`arc_length`) no step of the shortest arc converged: the path itself was lost there.
/// When no step converged at all, the start is named instead of a limit load.
std::string limit_load_text(const StepInfo& last,
                            const std::vector<std::pair<std::string, double>>& loads,
                            bool arc_length) {
  char text[640];
  std::snprintf(text, sizeof text,
                arc_length ? "the path could not be followed past load factor %.6g (t = %.6g, "
                             "step %d%s)"
                           : "the load could not be raised past load factor %.6g (t = %.6g, "
                             "step %d%s)",
                last.load_factor, last.time, last.step,
                last.negative_pivots < 0 ? ""
                : last.stable            ? ", stable"
                                         : ", not stable");
  std::string out = text;
  for (std::size_t k = 0; k < loads.size(); ++k) {
    std::snprintf(text, sizeof text, "%s %s = %.6g", k == 0 ? "; there" : ",",
                  loads[k].first.c_str(), loads[k].second);
    out += text;
  }
  if (arc_length)
    return out +
           ". No arc down to the shortest converged there: the path branches or turns too sharply "
           "for the arc length (a bifurcation: seed it with stability.imperfection), or an element "
           "inverts (a finer mesh there)";
  if (last.step == 0)
    return out +
           ": no step converged from the start. A body that cannot take the first increment of "
           "its load at any step size is seldom at a limit load: the reason of the failed "
           "attempts above says why (Newton's tolerances below the residual's round-off, a line "
           "search that cut every step, an element that inverts, an unresisted motion), and a "
           "load far above the material's modulus is often a unit slip";
  return out +
         ". If the body collapses there (its stiffness along the load is gone), this is its "
         "limit load. Under load control nothing follows it further: set solver.control: "
         "arc-length, which follows the load past its maximum, or prescribe a displacement "
         "instead (a cap's or a die's motion, a displacement condition, a cavity's volume). A run "
         "already driven by a motion has met a snap (the path "
         "turns back in that motion too, or jumps to another branch), which no step size "
         "follows: the steps up to it are its quasi-static path";
}

/// The recorder's last files and summary, the log's closing line, and the outcome: returns when
/// the run reached its end time, throws SolverError (with the command that resumes it, or the
/// last converged step) when a signal or the solver stopped it.
void finish_run(const RunContext& run, const SteppingResult& result, const StartTimes& times,
                const RunSolver& solver, RunRecorder& recorder, RunOutput& out) {
  const double memory = recorder.finish(result, times);
  const PhaseTimes phases = solver.stepper.times();
  char line[256];
  std::snprintf(line, sizeof line,
                "%s: %d steps, %d Newton iterations and %d Krylov steps (+%d solves with a reused "
                "factorisation), %d cut-backs, %.2fs (assembly %.2fs, linear solve %.2fs, output "
                "%.2fs), peak memory %.0f MiB",
                result.completed ? "done" : "stopped", result.steps, result.newton_iterations,
                result.krylov_steps, result.reused_solves, result.cutbacks,
                seconds_since(run.start), phases.assembly, phases.linear_solve,
                recorder.output_seconds(), memory);
  out.log().info(line);
  const StepInfo& last = recorder.last_step();
  const fs::path& directory = out.directory().directory();
  if (result.stopped_after_limit) {
    std::snprintf(line, sizeof line,
                  "ended past the limit load: the load factor fell to %.6g at step %d, below "
                  "solver.stop_load_factor = %.6g",
                  last.load_factor, last.step, run.c.solver.stop_load_factor);
    out.log().info(line);
  }
  if (result.stopped_unstable) {
    std::snprintf(line, sizeof line,
                  "ended at the instability: step %d (load factor %.6g) is unstable, the step "
                  "before it stable (solver.stability.stop_when_unstable)",
                  last.step, last.load_factor);
    out.log().info(line);
  }
  if (result.interrupted) {
    out.flush_log();
    // A resume must repeat the --set values (the checkpoint's fingerprint holds them); a
    // distributed run is resumed on as many ranks.
    if (!fs::exists(directory / "checkpoint.bin"))  // stopped before its first step converged
      throw SolverError(
          "interrupted during step 1, before a step converged: there is no "
          "checkpoint to resume from; start again with: " +
          rerun_command(run.options, solver.model->n_ranks(), directory));
    throw SolverError("interrupted after step " + std::to_string(last.step) +
                      " at t = " + std::to_string(last.time) + "; continue with: " +
                      resume_command(run.options, solver.model->n_ranks(), directory));
  }
  if (!result.completed) {
    out.log().error(result.failure);
    const std::string limit = result.smallest_step
                                  ? limit_load_text(last, recorder.last_loads(),
                                                    run.c.solver.control == StepControl::arc_length)
                                  : std::string();
    if (!limit.empty()) out.log().error(limit);
    out.flush_log();
    throw SolverError(result.failure + " (last converged step " + std::to_string(last.step) +
                      " at t = " + std::to_string(last.time) + " is written in " +
                      directory.string() + ")" + (limit.empty() ? std::string() : "\n" + limit));
  }
  out.flush_log();
}

}  // namespace

void run_case(const RunOptions& options) {
  const WallClock::time_point start = WallClock::now();
  // 1. Read the case and plan the run: the directory, the checkpoint to resume from, the --from
  //    state and every rule of the command line. Nothing is written yet.
  const Case c = parse_case_file(options.case_file, options.overrides);
  const RunPlan plan = plan_run(options, c);
  // 2. Read or generate the mesh; a checkpoint or --from state must belong to it.
  const RunMesh mesh = load_run_mesh(c, options);
  check_plan_against_mesh(plan, mesh.fingerprint);
  // 3. Build the parts of the model (materials, constraints, terms): everything that can be
  //    refused is refused before the run directory is touched.
  ModelParts parts = build_model_parts(c, mesh.mesh);
  run_pre_step_checks(PreStepStage::parts, c, mesh.mesh, &parts);
  // 4. Start PETSc with the run's options, the threads and the signal handlers; the ranks of a
  //    distributed run must have built the same mesh.
  const RunSession session(c, options.petsc_options);
  check_same_mesh_on_every_rank(mesh.mesh);
  const RunContext run{options, c, plan, mesh, session, start};
  session.run_collectively([&] {
    // 5. Make the model, its load stepper and the wrinkle meter.
    const auto t0 = WallClock::now();
    RunSolver solver(c, mesh.mesh, std::move(parts));
    const StartTimes times{start, mesh.seconds, seconds_since(t0)};
    // A --from state must fit the model before an --overwrite removes the earlier run.
    check_from_internal_values(plan, solver.model->n_internal_values());
    // 6. Take the run directory (lock, earlier run, temporaries) and open the log.
    RunOutput out(plan);
    log_header(run, out, solver);
    // 7. A resumed run restores the model and the stepper from its checkpoint.
    restore_checkpoint(plan, out.directory(), solver);
    // 8. Open the run's files: history.csv, solution.pvd (a resume cuts them back to its step).
    RunRecorder recorder(c, out.directory(),
                         {options.case_file, options.overrides, mesh.fingerprint}, *solver.model,
                         solver.stepper, solver.wrinkle_meter ? &*solver.wrinkle_meter : nullptr,
                         plan.resume ? &*plan.resume : nullptr);
    // 9. Set the starting state: --from's last state, or the initial state written as step 0.
    set_start(run, solver, recorder, out.log());
    // 10. Step to the end time, recording, logging and checkpointing every converged step.
    const SteppingResult result = step_to_the_end(run, solver, recorder, out);
    // 11. Write the last files and the summary, and report how the run ended.
    finish_run(run, result, times, solver, recorder, out);
  });
}

}  // namespace plisse::app
